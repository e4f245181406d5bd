// The fuzzy parameters of a study, as a parameter file declares them: one
// subsection per parameter is enough,
//
//   subsection Fuzzy parameter P1.E
//     set shape    = triangular
//     set values   = 0.95, 1, 1.05
//     set relative = true        # values are factors of the scene's value
//   end
//   subsection Fuzzy parameter P1.tip.force
//     set shape  = triangular
//     set values = 10e3, 50e3, 100e3
//   end
//
// and the list 'set fuzzy parameters = P1.E, P1.tip.force' is optional: it
// may name parameters (in the order of the outputs) that then need their
// subsection, and the subsections not in it follow in the file's order.
//
// Every name must be a quantity of the scene (scene_quantity.h); the support
// of each fuzzy number must be admissible for it (a modulus stays positive,
// a friction coefficient non-negative), and no two parameters may set the
// same value of the scene (P1.E and P1.root.E both set the modulus of zone
// root).

#ifndef fuzzycontact_fuzzy_fuzzy_parameters_h
#define fuzzycontact_fuzzy_fuzzy_parameters_h

#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_quantity.h>
#include <fuzzycontact/scene/scene_state.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  struct FuzzyParameter
  {
    SceneQuantity quantity;
    FuzzyNumber   number;
  };

  /**
   * A point of the parameters @p parameters as the user reads it:
   * "P1.E = 2.1e+11, P1.tip.force = 50000" (6 significant digits).
   */
  std::string
  point_text(const std::vector<FuzzyParameter> &parameters,
             const std::vector<double>         &values);

  class FuzzyParameterSet
  {
  public:
    /** Declares the list and one subsection per name known so far. */
    void
    declare_parameters(ParameterHandler &prm) const;

    /**
     * Every name of @p subsections that starts with "Fuzzy parameter " (the
     * top-level subsections of the parameter file,
     * Input::scan_parameter_text) declares a fuzzy parameter.
     */
    void
    add_names_of_subsections(const std::vector<std::string> &subsections);

    /**
     * Reads the list of names, followed by those of the subsections not in
     * it; true if the names changed.
     */
    bool
    learn_names(ParameterHandler &prm);

    /** Reads every fuzzy number and binds it to @p scene. */
    void
    parse_parameters(ParameterHandler &prm, const Scene &scene);

    const std::vector<FuzzyParameter> &
    parameters() const;
    std::vector<FuzzyNumber>
    numbers() const;
    std::vector<std::string>
    names() const;

    /**
     * The nominal state of @p scene with parameter i set to values[i]:
     * the one binding of fuzzy parameter values to a scene, from which every
     * model of a study is set.
     */
    SceneState
    state(const Scene &scene, const std::vector<double> &values) const;

  private:
    std::vector<std::string>    names_;
    std::vector<std::string>    names_of_subsections_;
    std::vector<FuzzyParameter> parameters_;
  };
} // namespace FuzzyContact

#endif
