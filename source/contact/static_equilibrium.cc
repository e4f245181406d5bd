// The static equilibrium of bodies held by contact alone: whether contact
// forces in the friction cones can balance their loads (Lawson and
// Hanson's NNLS on the cones' edges), the friction a load would need, and
// the check of a whole problem's load stages (contact_problem.h).

#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // x >= 0 minimising |A x - b| (A: rows x columns, few rows), by Lawson
    // and Hanson's NNLS; the least-squares solves on the passive set by the
    // pseudo-inverse.
    Vector<double>
    nonnegative_least_squares(const FullMatrix<double> &A,
                              const Vector<double>     &b)
    {
      const unsigned int m = A.m(), n = A.n();
      Vector<double>     x(n);
      std::vector<bool>  passive(n, false);
      const auto         residual = [&](const Vector<double> &y) {
        Vector<double> r(b);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < n; ++j)
            r[i] -= A(i, j) * y[j];
        return r;
      };
      // z on the passive set: argmin |A_P z - b|.
      const auto passive_solution = [&]() {
        std::vector<unsigned int> P;
        for (unsigned int j = 0; j < n; ++j)
          if (passive[j])
            P.push_back(j);
        LAPACKFullMatrix<double> AP(m, P.size());
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int c = 0; c < P.size(); ++c)
            AP(i, c) = A(i, P[c]);
        AP.compute_inverse_svd(1e-13);
        Vector<double> zP(P.size()), z(n);
        AP.vmult(zP, b);
        for (unsigned int c = 0; c < P.size(); ++c)
          z[P[c]] = zP[c];
        return z;
      };
      for (unsigned int outer = 0; outer < 3 * n + 10; ++outer)
        {
          const Vector<double> r      = residual(x);
          int                  best   = -1;
          double               w_best = 1e-14 * (b.l2_norm() + 1e-300);
          for (unsigned int j = 0; j < n; ++j)
            if (!passive[j])
              {
                double w = 0;
                for (unsigned int i = 0; i < m; ++i)
                  w += A(i, j) * r[i];
                if (w > w_best)
                  {
                    w_best = w;
                    best   = j;
                  }
              }
          if (best < 0)
            break;
          passive[best] = true;
          for (unsigned int inner = 0; inner < 3 * n + 10; ++inner)
            {
              const Vector<double> z    = passive_solution();
              double               step = 1;
              for (unsigned int j = 0; j < n; ++j)
                if (passive[j] && z[j] <= 0)
                  step = std::min(step, x[j] / (x[j] - z[j]));
              for (unsigned int j = 0; j < n; ++j)
                x[j] += step * (z[j] - x[j]);
              if (step == 1)
                break;
              for (unsigned int j = 0; j < n; ++j)
                if (passive[j] && x[j] <= 0)
                  {
                    passive[j] = false;
                    x[j]       = 0;
                  }
            }
        }
      return x;
    }
  } // namespace


  bool
  admissible_forces(const LoadStep            &step,
                    const std::vector<double> &mu,
                    Vector<double>            &p,
                    double                    *unbalanced)
  {
    const unsigned int r = step.n_motions();
    p.reinit(2 * mu.size());
    if (unbalanced != nullptr)
      *unbalanced = 0;
    Vector<double> b(r);
    for (unsigned int j = 0; j < r; ++j)
      b[j] = -step.rigid_load[j];
    if (r == 0 || b.l2_norm() == 0)
      return true;
    // The edges of node k's friction cone: p_n = 1, p_t = +-mu (one edge
    // without friction), as resultants along the free motions, normalised.
    const FullMatrix<double> &G = step.rigid->gaps;
    struct Edge
    {
      unsigned int node;
      double       t, norm;
    };
    std::vector<Edge>                edges;
    std::vector<std::vector<double>> columns;
    for (unsigned int k = 0; k < mu.size(); ++k)
      for (const double t : {1., -1.})
        {
          if (t < 0 && mu[k] == 0)
            continue;
          std::vector<double> a(r);
          double              norm = 0;
          for (unsigned int j = 0; j < r; ++j)
            {
              a[j] = G(normal_row(k), j) + t * mu[k] * G(tangential_row(k), j);
              norm += a[j] * a[j];
            }
          if (norm == 0)
            continue;
          norm = std::sqrt(norm);
          for (double &e : a)
            e /= norm;
          edges.push_back(Edge{k, t, norm});
          columns.push_back(std::move(a));
        }
    FullMatrix<double> A(r, edges.size());
    for (unsigned int c = 0; c < edges.size(); ++c)
      for (unsigned int j = 0; j < r; ++j)
        A(j, c) = columns[c][j];
    const Vector<double> q   = nonnegative_least_squares(A, b);
    Vector<double>       gap = b;
    for (unsigned int c = 0; c < edges.size(); ++c)
      {
        for (unsigned int j = 0; j < r; ++j)
          gap[j] -= A(j, c) * q[c];
        const unsigned int k = edges[c].node;
        p[normal_row(k)] += q[c] / edges[c].norm;
        p[tangential_row(k)] += edges[c].t * mu[k] * q[c] / edges[c].norm;
      }
    if (unbalanced != nullptr)
      *unbalanced = gap.l2_norm() / b.l2_norm();
    return gap.l2_norm() <= 1e-8 * b.l2_norm();
  }


  void
  check_equilibrium(const LoadStep            &step,
                    const std::vector<double> &mu,
                    const std::string         &what)
  {
    Vector<double> p;
    double         unbalanced = 0;
    if (admissible_forces(step, mu, p, &unbalanced))
      return;
    // The friction the body would need: the least factor s such that the
    // coefficients s mu can hold it (bisection on a logarithmic scale), if
    // one up to 1e3 can; none if it lifts off (or has no friction at all).
    const auto feasible = [&](const double s) {
      std::vector<double> scaled = mu;
      for (double &m : scaled)
        m *= s;
      return admissible_forces(step, scaled, p);
    };
    const double mu_max = *std::max_element(mu.begin(), mu.end());
    double       needed = 0;
    if (mu_max > 0 && feasible(1e3))
      {
        double low = 1, high = 1e3;
        for (unsigned int i = 0; i < 60 && high / low > 1 + 1e-12; ++i)
          {
            const double middle             = std::sqrt(low * high);
            (feasible(middle) ? high : low) = middle;
          }
        needed = high * mu_max;
      }
    std::ostringstream message;
    message << what << ": no static equilibrium (load step " << step.step
            << "): the bodies held by contact alone cannot be held by "
               "contact forces within the friction cones (|p_t| <= mu p_n): "
            << 100 * unbalanced
            << " % of the load's resultant along their free motions (";
    for (unsigned int j = 0; j < step.n_motions(); ++j)
      message << (j > 0 ? "; " : "") << step.rigid->names[j];
    message << ") is left unbalanced, so the body ";
    if (needed > 0)
      message << "slides: it needs friction coefficients "
              << std::setprecision(9) << needed / mu_max
              << " times the present ones (the largest, " << mu_max
              << ", would be " << needed
              << "). Raise the friction coefficient, hold it by a support, "
                 "or change the load.";
    else
      message << "slides or lifts off, whatever the friction. Hold it by a "
                 "support, or change the load.";
    AssertThrow(false, ExcNoStaticEquilibrium(message.str()));
  }


  bool
  has_static_equilibrium(const ContactProblem &problem,
                         const double          load_factor)
  {
    if (problem.rigid.size() == 0)
      return true;
    LoadStep step;
    step.step  = 0;
    step.rigid = &problem.rigid;
    Vector<double> p;
    if (problem.stages.empty())
      {
        step.rigid_load = problem.rigid_load;
        step.rigid_load *= load_factor;
        return admissible_forces(step, problem.mu, p);
      }
    Vector<double> held(problem.rigid.size());
    for (const GapLoadStage &stage : problem.stages)
      {
        held.add(load_factor, stage.rigid_load);
        step.rigid_load = held;
        if (!admissible_forces(step, problem.mu, p))
          return false;
      }
    return true;
  }
} // namespace FuzzyContact
