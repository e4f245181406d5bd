// The reference of every reanalysis: a new ARPACK solve on K(t), M(t).

#ifndef fuzzycontact_reanalysis_exact_resolve_h
#define fuzzycontact_reanalysis_exact_resolve_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** The reference: a new ARPACK solve on K(t), M(t). */
  class ExactResolve : public ReanalysisMethod
  {
  public:
    ExactResolve(const ParameterModel  &model,
                 const ModalParameters &modal_parameters);

    std::string
    name() const override;
    bool
    has_order() const override;
    ReanalysisResult
    reanalyse(const std::vector<double> &t,
              const unsigned int         order = 0) const override;

    /** The exact modes as a ModalBasis (with residuals). */
    ModalBasis
    solve(const std::vector<double> &t) const;

  private:
    const ParameterModel &model;
    ModalParameters       modal_parameters;
  };
} // namespace FuzzyContact

#endif
