#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/scene/scene_limits.h>
#include <fuzzycontact/study/input_checks.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  namespace InputChecks
  {
    void
    check(const ModalParameters &modal)
    {
      Input::integer_in_range(modal.n_modes,
                              1,
                              max_modes,
                              "Modal analysis: number of modes");
      Input::in_range(modal.tolerance,
                      min_solver_tolerance,
                      max_modal_tolerance,
                      "Modal analysis: tolerance",
                      "a relative eigenpair residual");
      Input::in_range(modal.shift,
                      -max_shift,
                      max_shift,
                      "Modal analysis: shift",
                      "an eigenvalue omega^2 in 1/s^2");
      Input::in_range(modal.cutoff_frequency,
                      0,
                      max_cutoff_frequency,
                      "Modal analysis: cutoff frequency",
                      "in Hz; 0 means none");
    }


    void
    check(const FL2CParameters &fl2c)
    {
      Input::integer_in_range(fl2c.max_iterations,
                              1,
                              max_fl2c_iterations,
                              "FL2C: max iterations");
      Input::in_range(fl2c.tolerance,
                      min_solver_tolerance,
                      max_solver_tolerance,
                      "FL2C: tolerance",
                      "a relative force change; below about 1e-14 round-off "
                      "never lets it converge");
      for (const double x : fl2c.gap_points)
        Input::in_range(x, -1e3, 1e3, "FL2C: gap points", "in m");
      for (const double x : fl2c.slip_points)
        Input::in_range(x, -1e3, 1e3, "FL2C: slip points", "in m");
      for (const double x : fl2c.force_points)
        Input::in_range(x, -1e12, 1e12, "FL2C: force points", "in N");
      for (const double x : fl2c.friction_points)
        Input::in_range(x, -1e12, 1e12, "FL2C: friction points", "in N");
    }


    void
    check(const ActiveSetParameters &exact)
    {
      Input::integer_in_range(exact.max_iterations,
                              1,
                              max_exact_iterations,
                              "Exact contact solver: max iterations");
      Input::in_range(exact.tolerance,
                      min_solver_tolerance,
                      max_solver_tolerance,
                      "Exact contact solver: tolerance");
    }


    void
    check(const OptimisationSettings &optimisation)
    {
      Input::integer_in_range(optimisation.max_iterations,
                              1,
                              max_optimisation_steps,
                              "Optimisation: iteration limit");
    }


    void
    check_modes_fit(const Scene       &scene,
                    const unsigned int refinements,
                    const unsigned int n_modes)
    {
      for (unsigned int c = 0; c < scene.components.size(); ++c)
        {
          const ComponentDescription &component = scene.components[c];
          // Clamped DoFs: both displacements of the nodes of each clamped
          // face (corners counted twice, which only errs on the safe side).
          double clamped = 0;
          for (const Support &s : component.all_supports())
            clamped += (s.fixed[0] + s.fixed[1]) *
                       (component.n_mesh_faces(s.face) *
                          std::ldexp(1.0, refinements) * component.fe_degree +
                        1);
          const double free =
            SceneLimits::n_dofs(scene, c, refinements) - clamped;
          const double needed = 2.0 * n_modes + 12;
          AssertThrow(
            free >= needed,
            ExcMessage(
              "Modal analysis: number of modes = " + std::to_string(n_modes) +
              " needs at least " + std::to_string(static_cast<long>(needed)) +
              " free DoFs per component, but component " + component.name +
              " of scene <" + scene.name + "> has only " +
              std::to_string(static_cast<long>(std::max(free, 0.))) +
              " after clamping. Ask for fewer modes, or refine "
              "(mesh refinements, the component's subdivisions "
              "or fe degree)."));
        }
    }


    std::vector<std::string>
    check_scene(const Scene       &scene,
                const std::string &scene_file,
                const unsigned int refinements,
                const bool         static_correction,
                const unsigned int n_modes,
                const std::string &key)
    {
      SceneLimits::check_memory(scene, refinements, static_correction, key);
      check_modes_fit(scene, refinements, n_modes);
      std::vector<std::string> warnings;
      for (const std::string &w : SceneLimits::warnings(scene))
        warnings.push_back("warning: " + scene_file + ": " + w);
      return warnings;
    }


    void
    check(const ModalParameters     &modal,
          const ActiveSetParameters &exact,
          const FL2CParameters      &fl2c)
    {
      check(modal);
      check(exact);
      check(fl2c);
    }


    namespace
    {
      // The length of the master face of @p pair.
      double
      master_face_length(const Scene &scene, const ContactPairDescription &pair)
      {
        const ComponentDescription &master =
          scene.components[scene.component_index(pair.master_component)];
        return master.face_length(pair.master_face);
      }
    } // namespace


    std::string
    all_crisp_warning(const FuzzyParameterSet &fuzzy)
    {
      for (const FuzzyParameter &p : fuzzy.parameters())
        if (p.number.points()[0] != p.number.points()[3])
          return "";
      return "warning: every fuzzy parameter is crisp (its support has no "
             "width): the outputs cannot change, and every membership "
             "function is a single value.";
    }


    void
    check(const FuzzyParameterSet &fuzzy,
          const Scene             &scene,
          const std::string       &contact_solver,
          const FL2CParameters    &fl2c,
          const double             penetration_tolerance)
    {
      for (const FuzzyParameter &p : fuzzy.parameters())
        {
          const std::string key   = "Fuzzy parameter " + p.quantity.name;
          const double      lower = p.number.points()[0];
          if (p.quantity.kind == SceneQuantity::Kind::gap)
            {
              const ContactPairDescription &pair =
                scene.contact_pairs[p.quantity.contact_pair];
              const double tolerance =
                penetration_tolerance * master_face_length(scene, pair);
              std::ostringstream message;
              message << key << ": initial penetration of " << -lower
                      << " m at the lower end of its support (the gap of "
                         "contact pair "
                      << pair.name << " would be " << lower << " m); at most "
                      << tolerance
                      << " m is accepted as round-off. Set values whose "
                         "support starts at a non-negative gap.";
              AssertThrow(lower >= -tolerance, ExcMessage(message.str()));
            }
          const bool moves_w_or_gaps =
            p.quantity.kind == SceneQuantity::Kind::youngs_modulus ||
            p.quantity.kind == SceneQuantity::Kind::load ||
            p.quantity.kind == SceneQuantity::Kind::gap;
          AssertThrow(
            !(Utilities::trim(contact_solver) == "fl2c" &&
              fl2c.calibration == FL2CParameters::Calibration::prm &&
              fl2c.coarse_correction ==
                FL2CParameters::CoarseCorrection::none &&
              moves_w_or_gaps),
            ExcMessage(
              "FL2C: calibration = prm with coarse correction = none and the "
              "fuzzy parameter " +
              p.quantity.name +
              ": the absolute transition points cannot be calibrated for "
              "the whole parameter box (their gain must stay below 2 / W_nn "
              "of every node for the sweeps to converge, and " +
              p.quantity.name +
              " changes the contact flexibility or the penetrations while "
              "the points stay fixed). Set FL2C: calibration = automatic, "
              "or coarse correction = active set."));
        }
    }


    Scene
    SceneReader::operator()(const std::string &file)
    {
      Scene scene = Scene::read(file);
      AssertThrow(!scene.contact_pairs.empty(),
                  ExcMessage("Scene file <" + file +
                             "> has no contact pairs; a contact study needs "
                             "at least one ('contact pairs' in subsection "
                             "Scene)."));
      for (const std::string &w :
           check_scene(scene, file, refinements, static_correction, n_modes))
        warnings.push_back(w);
      return scene;
    }
  } // namespace InputChecks
} // namespace FuzzyContact
