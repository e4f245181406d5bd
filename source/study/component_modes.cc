#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/reduction/reduced_component.h>
#include <fuzzycontact/study/component_modes.h>

#include <memory>
#include <string>

namespace FuzzyContact
{
  std::vector<ModalBasis>
  component_modes(const ContactScene      &bodies,
                  const ModalParameters   &parameters,
                  TimerOutput             *timer,
                  const std::vector<bool> &owned)
  {
    // At shift 0, ARPACK works on the factorisation of K that the static
    // correction uses too.
    const ModalSolver       solver(parameters);
    std::vector<ModalBasis> modes;
    for (unsigned int c = 0; c < bodies.n_components(); ++c)
      {
        const Component  &component = bodies.component(c);
        const std::string what      = "Component " + component.name();
        if (!owned.empty() && !owned[c])
          {
            modes.emplace_back(); // not needed, or built on another rank
            continue;
          }
        if (parameters.shift == 0)
          {
            const auto factorisation = bodies.stiffness_factorisation(c, timer);
            auto       scope         = timer_section(timer, "modes (ARPACK)");
            modes.push_back(solver.solve(component.stiffness_matrix(),
                                         component.mass_matrix(),
                                         *factorisation,
                                         what));
          }
        else
          {
            auto scope = timer_section(timer, "modes (ARPACK)");
            modes.push_back(solver.solve(component.stiffness_matrix(),
                                         component.mass_matrix(),
                                         what));
          }
        ProgressLines::stage("modes of " + component.name() + " done",
                             c + 1,
                             bodies.n_components());
      }
    return modes;
  }


  void
  truncate_to_static_error(std::vector<ModalBasis> &modes,
                           const ContactScene      &bodies,
                           const unsigned int       node,
                           const double             tolerance)
  {
    const ContactInterface &interface = bodies.interface();
    for (unsigned int c = 0; c < bodies.n_components(); ++c)
      {
        // The component's part of the node's normal flexibility.
        const Component &component = bodies.component(c);
        const auto      &C         = interface.gap_operator(c);
        Vector<double>   f(component.n_dofs());
        for (auto it = C.begin(normal_row(node)); it != C.end(normal_row(node));
             ++it)
          f[it->column()] = it->value();
        if (f.linfty_norm() == 0)
          continue;
        Vector<double> u = f;
        bodies.stiffness_factorisation(c)->solve(u);
        const unsigned int n =
          modes_for_static_error(modes[c],
                                 f,
                                 u,
                                 tolerance,
                                 "Component " + component.name());
        modes[c].eigenvalues.resize(n);
        modes[c].modes.resize(n);
        modes[c].residuals.resize(n);
      }
  }
} // namespace FuzzyContact
