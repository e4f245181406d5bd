// The static equilibrium of bodies held by contact alone: whether contact
// forces in the friction cones can balance their loads (Lawson and
// Hanson's NNLS on the cones' edges), the friction a load would need, and
// the check of a whole problem's load stages (static_equilibrium.h).

#include <fuzzycontact/contact/static_equilibrium.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace FuzzyContact
{
  namespace
  {
    // A few rows (the free motions), many columns (the cones' edges),
    // stored column after column.
    struct EdgeMatrix
    {
      unsigned int        m = 0, n = 0;
      std::vector<double> entries;

      const double *
      column(const unsigned int j) const
      {
        return &entries[j * m];
      }
    };

    // z on the passive set P: argmin |A_P z - b|, by a QR factorisation of
    // A_P (Gram-Schmidt twice: A has a few rows, so that the solve costs
    // next to nothing; a study checks every evaluation), or by the
    // pseudo-inverse (SVD) where A_P's columns are close to dependent (a
    // column keeps less than 1e-6 of its norm).
    void
    passive_solution(const EdgeMatrix                &A,
                     const Vector<double>            &b,
                     const std::vector<unsigned int> &P,
                     std::vector<double>             &z)
    {
      const unsigned int m = A.m, k = P.size();
      std::fill(z.begin(), z.end(), 0.);
      std::vector<double> Q(m * k), R(k * k, 0.);
      bool                independent = k <= m;
      for (unsigned int c = 0; c < k && independent; ++c)
        {
          double *q = &Q[c * m];
          std::copy(A.column(P[c]), A.column(P[c]) + m, q);
          double norm0 = 0;
          for (unsigned int i = 0; i < m; ++i)
            norm0 += q[i] * q[i];
          for (unsigned int pass = 0; pass < 2; ++pass)
            for (unsigned int d = 0; d < c; ++d)
              {
                const double *qd = &Q[d * m];
                double        h  = 0;
                for (unsigned int i = 0; i < m; ++i)
                  h += qd[i] * q[i];
                R[d * k + c] += h;
                for (unsigned int i = 0; i < m; ++i)
                  q[i] -= h * qd[i];
              }
          double norm = 0;
          for (unsigned int i = 0; i < m; ++i)
            norm += q[i] * q[i];
          independent  = norm0 > 0 && norm > 1e-12 * norm0;
          norm         = std::sqrt(norm);
          R[c * k + c] = norm;
          for (unsigned int i = 0; i < m; ++i)
            q[i] /= norm;
        }
      if (independent)
        {
          for (unsigned int c = k; c-- > 0;)
            {
              double v = 0;
              for (unsigned int i = 0; i < m; ++i)
                v += Q[c * m + i] * b[i];
              for (unsigned int d = c + 1; d < k; ++d)
                v -= R[c * k + d] * z[P[d]];
              z[P[c]] = v / R[c * k + c];
            }
          return;
        }
      LAPACKFullMatrix<double> AP(m, k);
      for (unsigned int c = 0; c < k; ++c)
        for (unsigned int i = 0; i < m; ++i)
          AP(i, c) = A.column(P[c])[i];
      AP.compute_inverse_svd(1e-13);
      Vector<double> zP(k);
      AP.vmult(zP, b);
      for (unsigned int c = 0; c < k; ++c)
        z[P[c]] = zP[c];
    }

    // x >= 0 minimising |A x - b| (A: rows x columns, few rows), by Lawson
    // and Hanson's NNLS.
    std::vector<double>
    nonnegative_least_squares(const EdgeMatrix &A, const Vector<double> &b)
    {
      const unsigned int        m = A.m, n = A.n;
      std::vector<double>       x(n, 0.), z(n, 0.), r(m);
      std::vector<bool>         passive(n, false);
      std::vector<unsigned int> P;
      const double              w_floor = 1e-14 * (b.l2_norm() + 1e-300);
      for (unsigned int outer = 0; outer < 3 * n + 10; ++outer)
        {
          for (unsigned int i = 0; i < m; ++i)
            r[i] = b[i];
          for (const unsigned int j : P)
            for (unsigned int i = 0; i < m; ++i)
              r[i] -= A.column(j)[i] * x[j];
          int    best   = -1;
          double w_best = w_floor;
          for (unsigned int j = 0; j < n; ++j)
            if (!passive[j])
              {
                const double *a = A.column(j);
                double        w = 0;
                for (unsigned int i = 0; i < m; ++i)
                  w += a[i] * r[i];
                if (w > w_best)
                  {
                    w_best = w;
                    best   = j;
                  }
              }
          if (best < 0)
            break;
          passive[best] = true;
          P.push_back(best);
          for (unsigned int inner = 0; inner < 3 * n + 10; ++inner)
            {
              passive_solution(A, b, P, z);
              double step = 1;
              for (const unsigned int j : P)
                if (z[j] <= 0)
                  step = std::min(step, x[j] / (x[j] - z[j]));
              for (const unsigned int j : P)
                x[j] += step * (z[j] - x[j]);
              if (step == 1)
                break;
              std::vector<unsigned int> kept;
              for (const unsigned int j : P)
                if (x[j] <= 0)
                  {
                    passive[j] = false;
                    x[j]       = 0;
                  }
                else
                  kept.push_back(j);
              P.swap(kept);
            }
        }
      return x;
    }

    // The NNLS test of admissible_forces() itself.
    bool
    solve_admissible_forces(const LoadStep            &step,
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
      std::vector<Edge> edges;
      edges.reserve(2 * mu.size());
      EdgeMatrix A;
      A.m = r;
      A.entries.reserve(2 * mu.size() * r);
      for (unsigned int k = 0; k < mu.size(); ++k)
        for (const double t : {1., -1.})
          {
            if (t < 0 && mu[k] == 0)
              continue;
            const std::size_t start = A.entries.size();
            double            norm  = 0;
            for (unsigned int j = 0; j < r; ++j)
              {
                const double a =
                  G(normal_row(k), j) + t * mu[k] * G(tangential_row(k), j);
                A.entries.push_back(a);
                norm += a * a;
              }
            if (norm == 0)
              {
                A.entries.resize(start);
                continue;
              }
            norm = std::sqrt(norm);
            for (std::size_t e = start; e < A.entries.size(); ++e)
              A.entries[e] /= norm;
            edges.push_back(Edge{k, t, norm});
          }
      A.n                           = edges.size();
      const std::vector<double> q   = nonnegative_least_squares(A, b);
      Vector<double>            gap = b;
      for (unsigned int c = 0; c < edges.size(); ++c)
        if (q[c] != 0)
          {
            for (unsigned int j = 0; j < r; ++j)
              gap[j] -= A.column(c)[j] * q[c];
            const unsigned int k = edges[c].node;
            p[normal_row(k)] += q[c] / edges[c].norm;
            p[tangential_row(k)] += edges[c].t * mu[k] * q[c] / edges[c].norm;
          }
      if (unbalanced != nullptr)
        *unbalanced = gap.l2_norm() / b.l2_norm();
      return gap.l2_norm() <= 1e-8 * b.l2_norm();
    }

    // The last few answers of admissible_forces(), by their whole input.
    // The same test recurs with the same load, geometry and friction at
    // every cold start of a point (the exact solver's attempts and the
    // frictionless start of each, its path, the probes of a failed point
    // with more friction: the frictionless test there does not depend on
    // the friction), and on a fine mesh one test can cost as much as the
    // contact solve (the pin of prm/pin.prm at two refinements, 1026 cone
    // edges on 3 free motions: the edges of neighbouring nodes are nearly
    // parallel, and the NNLS's passive sets go through the pseudo-inverse
    // again and again). An input compared entry by entry, so a hit is the
    // test's own answer. The bisection of least_friction_factor(), whose
    // tests are each new, goes without them.
    struct AdmissibleAnswer
    {
      FullMatrix<double>  gaps;
      Vector<double>      load;
      std::vector<double> mu;
      bool                admissible;
      Vector<double>      p;
      double              unbalanced;
    };
    // (Most recently used first.)
    thread_local std::vector<AdmissibleAnswer> answers;
    constexpr unsigned int                     kept_answers = 4;
  } // namespace


  bool
  admissible_forces(const LoadStep            &step,
                    const std::vector<double> &mu,
                    Vector<double>            &p,
                    double                    *unbalanced)
  {
    if (step.n_motions() == 0)
      return solve_admissible_forces(step, mu, p, unbalanced);
    const FullMatrix<double> &G = step.rigid->gaps;
    for (auto a = answers.begin(); a != answers.end(); ++a)
      if (a->mu == mu && a->load.size() == step.rigid_load.size() &&
          a->load == step.rigid_load && a->gaps.m() == G.m() &&
          a->gaps.n() == G.n() && a->gaps == G)
        {
          std::rotate(answers.begin(), a, a + 1);
          p = answers.front().p;
          if (unbalanced != nullptr)
            *unbalanced = answers.front().unbalanced;
          return answers.front().admissible;
        }
    double     fraction   = 0;
    const bool admissible = solve_admissible_forces(step, mu, p, &fraction);
    if (unbalanced != nullptr)
      *unbalanced = fraction;
    if (answers.size() == kept_answers)
      answers.pop_back();
    answers.insert(
      answers.begin(),
      AdmissibleAnswer{G, step.rigid_load, mu, admissible, p, fraction});
    return admissible;
  }


  double
  least_friction_factor(const LoadStep            &step,
                        const std::vector<double> &mu,
                        double                     low,
                        double                     high,
                        const double               distance_tolerance)
  {
    Assert(low >= 0 && high > low, ExcInternalError());
    Assert(distance_tolerance >= 0, ExcInternalError());
    std::vector<double> scaled(mu.size());
    Vector<double>      p;
    for (unsigned int i = 0; i < 100 && high - low > 1e-12 * high; ++i)
      {
        if (distance_tolerance > 0 &&
            high - low <= distance_tolerance * std::abs(1 - high))
          break;
        const double middle =
          low > 0 ? std::sqrt(low * high) : (low + high) / 2;
        for (unsigned int k = 0; k < mu.size(); ++k)
          scaled[k] = middle * mu[k];
        // (Each test of the bisection is new: not kept.)
        (solve_admissible_forces(step, scaled, p, nullptr) ? high : low) =
          middle;
      }
    return high;
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
    std::vector<double> scaled = mu;
    for (double &m : scaled)
      m *= 1e3;
    const double mu_max = *std::max_element(mu.begin(), mu.end());
    double       needed = 0;
    if (mu_max > 0 && admissible_forces(step, scaled, p))
      needed = least_friction_factor(step, mu, 1, 1e3) * mu_max;
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
