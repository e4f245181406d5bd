// One case of a modal reanalysis study (step-2), as a parameter file
// describes it in a subsection 'Case <name>': a component of a scene, the
// parameters declared variable (reanalysis_parameters.h), and samples of
// their changes in percent:
//
//   subsection Case b
//     set description        = E of the half next to the clamp +5 %, +20 %
//     set scene              = cantilever-zones.prm
//     set component          = beam
//     set parameters         = beam.root.E
//     set changes in percent = 5; 20
//   end

#ifndef fuzzycontact_reanalysis_reanalysis_case_h
#define fuzzycontact_reanalysis_reanalysis_case_h

#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  struct ReanalysisCase
  {
    std::string              name;
    std::string              description;
    std::string              scene_file;
    std::string              component;
    std::vector<std::string> parameters;
    /** Relative changes, one vector per sample (one change per parameter). */
    std::vector<std::vector<double>> samples;
    /** The same in percent, as given. */
    std::vector<std::vector<double>> samples_percent;

    /** Declares the subsection 'Case <@p name>'. */
    static void
    declare_parameters(ParameterHandler &prm, const std::string &name);

    /**
     * Reads the subsection 'Case <@p name>'; the scene file is read
     * relative to @p prm_file. Throws a message naming the case (and the
     * sample) if a value is malformed or a sample does not give one change
     * per parameter.
     */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &name,
                     const std::string &prm_file);

    /**
     * Checks against @p scene what can be checked without a mesh: the
     * component exists, the parameters name its moduli or densities and
     * are distinct, and no sample makes a modulus or density non-positive.
     * Messages start with "Case <name>: " or "Case <name>, sample <s>: ".
     */
    void
    check(const Scene &scene) const;
  };
} // namespace FuzzyContact

#endif
