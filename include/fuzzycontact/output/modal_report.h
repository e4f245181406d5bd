// The report of a modal analysis (step-1): for each component its modes
// beside beam theory, the comparison with a published table of
// frequencies in both 2D models, and a mesh-convergence table. The text
// goes to the screen and report.txt, the figures to results.json, and the
// mode shapes to one VTU file per component, all written at the end of a
// successful run.

#ifndef fuzzycontact_output_modal_report_h
#define fuzzycontact_output_modal_report_h

#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_classification.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/scene/scene.h>

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** The modes of a component in one 2D model (frequencies and kinds). */
  struct PlaneModelModes
  {
    PlaneModel            model;
    std::vector<double>   frequencies;
    std::vector<ModeKind> kinds;
  };

  /** The modes of a component on one mesh of a convergence study. */
  struct MeshLevelModes
  {
    unsigned int        refinement;
    unsigned int        n_dofs;
    std::vector<double> frequencies;
    double              max_residual;
    /** Wall time of the stages "mesh and DoFs", "assembly", "eigenvalues
     * (ARPACK)" [s]. */
    std::map<std::string, double> stage_times;
  };

  class ModalReport
  {
  public:
    explicit ModalReport(const std::string &output_directory);

    /** The first line, for @p scene read from @p scene_file. */
    void
    start(const Scene &scene, const std::string &scene_file);

    /**
     * The modes @p basis of @p component (its mesh refined
     * @p mesh_refinements times), with their kinds and, if @p theory is not
     * empty, beam theory; and the mode shapes for ParaView.
     */
    void
    add_component(const Component                        &component,
                  const unsigned int                      mesh_refinements,
                  const ModalBasis                       &basis,
                  const std::vector<ModeKind>            &kinds,
                  const std::vector<BeamTheoryFrequency> &theory);

    /**
     * The published frequencies @p paper (modes up to @p cutoff_frequency)
     * beside the nearest mode of @p component in each 2D model of
     * @p models: which model explains each published mode (a match is a
     * difference below 1 %), which modes the paper does not list.
     */
    void
    add_paper_comparison(const ComponentDescription         &component,
                         const double                        cutoff_frequency,
                         const std::vector<double>          &paper,
                         const std::vector<PlaneModelModes> &models);

    /**
     * The mesh-convergence table of @p component, against the
     * @p extrapolated frequencies.
     */
    void
    add_convergence(const ComponentDescription        &component,
                    const std::vector<MeshLevelModes> &levels,
                    const std::vector<double>         &extrapolated);

    /** Writes report.txt, results.json and modes-*.vtu, and says so. */
    void
    write();

  private:
    Report         report;
    OutputFiles    output;
    nlohmann::json results;
  };
} // namespace FuzzyContact

#endif
