// The solutions of FullOrderContact (contact/full_order_contact.h): the
// outputs alone from the active set solution on W, or the displacement
// fields solved accurately, with the forces refined on their gaps.

#include <fuzzycontact/contact/full_order_contact.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <functional>

namespace FuzzyContact
{
  // Forces and residual from the active set solution on W; the observed
  // displacements from the load responses and the kept columns.
  ContactSolution
  FullOrderContact::outputs_only(const ContactState &state)
  {
    ContactSolution solution;
    solution.p        = state.p;
    solution.g        = state.g;
    solution.status   = state.status;
    solution.residual = state.residual;
    for (unsigned int j = 0; j < state.p.size(); ++j)
      if (state.p[j] != 0)
        prepare_column(j);
    solution.rigid = state.rigid;
    solution.observed.resize(components.size());
    for (unsigned int c = 0; c < components.size(); ++c)
      for (unsigned int i = 0; i < observed_dofs[c].size(); ++i)
        {
          const types::global_dof_index dof = observed_dofs[c][i];
          double u = observed_displacement(c, i, dof, state.p);
          for (unsigned int j = 0; j < components[c]->free_motions().size();
               ++j)
            u += state.rigid[first_motion_[c] + j] *
                 components[c]->free_motions()[j][dof];
          solution.observed[c].push_back(u);
        }
    return solution;
  }


  // Displacements u_c = K_c^{-1} (lambda f_c + C_c^T p), and the residual
  // of their own gaps g0 + C u. The columns of W carry the error of a plain
  // back-substitution (up to 1e-9 relative on fine meshes, from the
  // condition of K), so the forces are refined with the gaps of the
  // accurately solved displacements: W's restriction to the final active
  // set maps the remaining constraint violation to a force correction.
  ContactSolution
  FullOrderContact::with_fields(const ContactState   &state,
                                const Vector<double> &g_previous,
                                FlexibilityOperator  &W)
  {
    ContactState        final_state = state;
    ContactSolution     solution;
    std::vector<double> cn(interface.n_nodes(), 0), ct(interface.n_nodes(), 0);
    const std::function<double(unsigned int)> c_n = [&](const unsigned int k) {
      if (cn[k] == 0)
        {
          prepare_column(normal_row(k));
          cn[k] = 1. / entry(normal_row(k), normal_row(k));
        }
      return cn[k];
    };
    const std::function<double(unsigned int)> c_t = [&](const unsigned int k) {
      if (ct[k] == 0)
        {
          prepare_column(tangential_row(k));
          ct[k] = 1. / entry(tangential_row(k), tangential_row(k));
        }
      return ct[k];
    };
    Vector<double> g_free = initial_gaps_;
    g_free.add(load_factor_, load_gaps());
    // The equilibrium of the bodies held by contact alone at full load.
    LoadStep full_load;
    full_load.rigid      = rigid_.size() > 0 ? &rigid_ : nullptr;
    full_load.rigid_load = rigid_load();
    if (full_load.rigid_load.size() > 0)
      full_load.rigid_load *= load_factor_;
    for (unsigned int refinement = 0;; ++refinement)
      {
        solution.displacements.clear();
        for (unsigned int c = 0; c < components.size(); ++c)
          {
            Vector<double> rhs(components[c]->n_dofs());
            interface.gap_operator(c).Tvmult(rhs, final_state.p);
            rhs.add(load_factor_, load_vector(c));
            solution.displacements.push_back(accurate_solve(c, rhs));
            add_free_motions(c, final_state.rigid, solution.displacements[c]);
          }
        solution.g = initial_gaps_;
        for (unsigned int c = 0; c < components.size(); ++c)
          interface.gap_operator(c).vmult_add(solution.g,
                                              solution.displacements[c]);
        const std::vector<double> r = complementarity_residuals(final_state.p,
                                                                solution.g,
                                                                g_previous,
                                                                friction_,
                                                                c_n,
                                                                c_t);
        const double              worst = *std::max_element(r.begin(), r.end());
        const double scale = residual_scale(final_state.p, g_free, c_n);
        solution.residual =
          std::max(worst == 0 ? 0. : worst / scale,
                   equilibrium_residual(full_load, final_state.p, scale));
        if (solution.residual <= solver.parameters().tolerance ||
            refinement == 3)
          break;
        Vector<double> violation = solution.g;
        for (unsigned int k = 0; k < interface.n_nodes(); ++k)
          violation[tangential_row(k)] -= g_previous[tangential_row(k)];
        Vector<double> imbalance = full_load.rigid_load;
        for (unsigned int j = 0; j < rigid_.size(); ++j)
          for (unsigned int i = 0; i < final_state.p.size(); ++i)
            imbalance[j] += rigid_.gaps(i, j) * final_state.p[i];
        const ContactState change = solver.correction(W,
                                                      final_state,
                                                      friction_,
                                                      violation,
                                                      full_load.rigid,
                                                      imbalance);
        final_state.p += change.p;
        if (change.rigid.size() > 0) // (no body held by contact alone)
          final_state.rigid += change.rigid;
      }
    solution.p      = final_state.p;
    solution.rigid  = final_state.rigid;
    solution.status = final_state.status;
    solution.observed.resize(components.size());
    for (unsigned int c = 0; c < components.size(); ++c)
      for (const types::global_dof_index dof : observed_dofs[c])
        solution.observed[c].push_back(solution.displacements[c][dof]);
    return solution;
  }


  Vector<double>
  FullOrderContact::accurate_solve(const unsigned int    c,
                                   const Vector<double> &rhs)
  {
    // K = s K_ref: u = K_ref^{-1} rhs / s, then one step of iterative
    // refinement with the residual accumulated in long double.
    const Factorized &F = factorized[c];
    Vector<double>    u = rhs;
    F.inverse->solve(u);
    u /= F.scale;
    const SparseMatrix<double> &K = components[c]->stiffness_matrix();
    Vector<double>              r(rhs.size());
    for (unsigned int i = 0; i < rhs.size(); ++i)
      {
        long double sum = rhs[i];
        for (auto it = K.begin(i); it != K.end(i); ++it)
          sum -= static_cast<long double>(it->value()) * u[it->column()];
        r[i] = static_cast<double>(sum);
      }
    F.inverse->solve(r);
    u.add(1. / F.scale, r);
    back_substitutions += 2;
    return u;
  }
} // namespace FuzzyContact
