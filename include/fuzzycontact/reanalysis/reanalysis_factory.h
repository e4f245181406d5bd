// Making a reanalysis method from its name, as a parameter file names it:
//
//   taylor    first-order Taylor series (first_order_taylor.h)
//   ca        Kirsch's Combined Approximations (combined_approximations.h)
//   hptp      HPTP with a basis per sample (homotopy_perturbation.h)
//   hptp-pi   the parameter-independent HPTP
//             (parameter_independent_reanalysis.h)
//
// The exact re-solve (exact_resolve.h), the reference of them all, is not
// made here: it needs the settings of a modal analysis, not of a
// reanalysis.

#ifndef fuzzycontact_reanalysis_reanalysis_factory_h
#define fuzzycontact_reanalysis_reanalysis_factory_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** The names create_reanalysis_method() knows, in the order above. */
  const std::vector<std::string> &
  reanalysis_method_names();

  /**
   * The method called @p name, prepared ("offline") for the parameters of
   * @p model around the nominal modes @p nominal, with the maximum order,
   * truncation tolerance and cluster gap of @p settings. Taylor, CA and
   * HPTP keep references to @p model and @p nominal, which must outlive
   * them; the parameter-independent HPTP copies what it needs (and keeps a
   * reference to the model's component). Throws a message listing the
   * names if @p name is none of them.
   */
  std::unique_ptr<ReanalysisMethod>
  create_reanalysis_method(const std::string        &name,
                           const ParameterModel     &model,
                           const ModalBasis         &nominal,
                           const ReanalysisSettings &settings);
} // namespace FuzzyContact

#endif
