// The local problems of the optimisation method, on Trilinos ROL through
// deal.II's ROL vector adaptor (the only translation unit that includes
// ROL's headers).

#include <fuzzycontact/fuzzy/local_optimisation.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/optimization/rol/vector_adaptor.h>

#include <ROL_Bounds.hpp>
#include <ROL_Objective.hpp>
#include <ROL_Problem.hpp>
#include <ROL_Solver.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    using namespace dealii;

    Normalisation::Normalisation(const std::vector<FuzzyNumber> &parameters)
    {
      for (unsigned int d = 0; d < parameters.size(); ++d)
        {
          const Interval support = parameters[d].alpha_cut(0);
          supports.push_back(support);
          if (support.width() > 0)
            free.push_back(d);
          fixed.push_back(parameters[d].alpha_cut(1).midpoint());
        }
    }


    unsigned int
    Normalisation::n_free() const
    {
      return free.size();
    }


    std::vector<double>
    Normalisation::parameters(const VectorType &x) const
    {
      std::vector<double> p = fixed;
      for (unsigned int i = 0; i < free.size(); ++i)
        {
          const Interval &s = supports[free[i]];
          p[free[i]]        = x[i] <= 0   ? s.lower
                              : x[i] >= 1 ? s.upper
                                          : s.lower + x[i] * s.width();
        }
      return p;
    }


    double
    Normalisation::coordinate(const unsigned int i, const double p) const
    {
      const Interval &s = supports[free[i]];
      if (p == s.lower)
        return 0;
      if (p == s.upper)
        return 1;
      return (p - s.lower) / s.width();
    }


    std::pair<VectorType, VectorType>
    Normalisation::box(const std::vector<FuzzyNumber> &parameters,
                       const double                    alpha) const
    {
      VectorType lo(n_free()), hi(n_free());
      for (unsigned int i = 0; i < free.size(); ++i)
        {
          const Interval cut = parameters[free[i]].alpha_cut(alpha);
          lo[i]              = coordinate(i, cut.lower);
          hi[i]              = coordinate(i, cut.upper);
        }
      return {lo, hi};
    }


    OutputObjective::OutputObjective(EvaluationCache     &cache,
                                     const Normalisation &normalisation,
                                     const unsigned int   output,
                                     const double         sign,
                                     const double         scale,
                                     const double         step,
                                     const VectorType    &lower,
                                     const VectorType    &upper)
        : cache(cache)
        , normalisation(normalisation)
        , output(output)
        , sign(sign)
        , scale(scale)
        , step(step)
        , lower(lower)
        , upper(upper)
    {
    }


    double
    OutputObjective::at(const VectorType &x)
    {
      const std::vector<double> &s = cache(normalisation.parameters(x));
      if (!has_solution(s))
        return std::numeric_limits<double>::infinity();
      AssertThrow(output < s.size(),
                  ExcMessage("The response returned " +
                             std::to_string(s.size()) + " outputs; output " +
                             std::to_string(output + 1) + " was asked for."));
      AssertThrow(std::isfinite(s[output]),
                  ExcMessage("The response returned a non-finite value."));
      return sign * s[output] / scale;
    }


    void
    OutputObjective::prefetch(const std::vector<VectorType> &xs)
    {
      std::vector<std::vector<double>> points;
      for (const VectorType &x : xs)
        points.push_back(normalisation.parameters(x));
      cache.prefetch(points);
    }


    void
    OutputObjective::gradient_at(VectorType &grad, const VectorType &x0)
    {
      // The points the loop below evaluates.
      std::vector<VectorType> points;
      for (unsigned int i = 0; i < x0.size(); ++i)
        {
          const double up   = std::min(x0[i] + step, upper[i]);
          const double down = std::max(x0[i] - step, lower[i]);
          for (const double end : {up, down})
            if (up - down > 0)
              {
                points.push_back(x0);
                points.back()[i] = end;
              }
        }
      prefetch(points);
      VectorType xp = x0;
      for (unsigned int i = 0; i < x0.size(); ++i)
        {
          const double up   = std::min(x0[i] + step, upper[i]);
          const double down = std::max(x0[i] - step, lower[i]);
          if (up - down <= 0)
            {
              grad[i] = 0; // a crisp level: no room to move
              continue;
            }
          xp[i]           = up;
          const double fp = at(xp);
          xp[i]           = down;
          const double fm = at(xp);
          xp[i]           = x0[i];
          // One-sided where a side has no solution, none where neither
          // has.
          const double f0 =
            (std::isfinite(fp) && std::isfinite(fm)) ? 0. : at(x0);
          grad[i] = std::isfinite(fp) && std::isfinite(fm)
                      ? (fp - fm) / (up - down)
                    : std::isfinite(fp) && std::isfinite(f0) && up > x0[i]
                      ? (fp - f0) / (up - x0[i])
                    : std::isfinite(fm) && std::isfinite(f0) && down < x0[i]
                      ? (f0 - fm) / (x0[i] - down)
                      : 0.;
        }
    }


    namespace
    {
      using Adaptor = Rol::VectorAdaptor<VectorType>;

      const VectorType &
      unwrap(const ROL::Vector<double> &x)
      {
        return *static_cast<const Adaptor &>(x).getVector();
      }

      VectorType &
      unwrap(ROL::Vector<double> &x)
      {
        return *static_cast<Adaptor &>(x).getVector();
      }

      // An OutputObjective as ROL sees it.
      class RolObjective : public ROL::Objective<double>
      {
      public:
        explicit RolObjective(OutputObjective &objective)
            : objective(objective)
        {
        }

        double
        value(const ROL::Vector<double> &x, double & /*tol*/) override
        {
          // A point without a solution: a barrier far above every value
          // ROL has seen, so that its line search steps back.
          const double f = objective.at(unwrap(x));
          if (std::isfinite(f))
            {
              largest = std::max(largest, std::abs(f));
              return f;
            }
          return 1e3 * (1 + largest);
        }

        void
        gradient(ROL::Vector<double>       &g,
                 const ROL::Vector<double> &x,
                 double & /*tol*/) override
        {
          VectorType       &grad = unwrap(g);
          const VectorType &x0   = unwrap(x);
          objective.gradient_at(grad, x0);
        }

      private:
        OutputObjective &objective;
        double           largest = 0;
      };

      // ROL's parameters for the algorithm and tolerances of @p settings.
      ROL::ParameterList
      rol_parameters(const OptimisationSettings &settings)
      {
        ROL::ParameterList list;
        list.sublist("General").set("Output Level", 0);
        list.sublist("General").sublist("Secant").set("Type",
                                                      "Limited-Memory BFGS");
        if (settings.algorithm == "quasi-newton")
          {
            list.sublist("Step").set("Type", "Line Search");
            list.sublist("Step")
              .sublist("Line Search")
              .sublist("Descent Method")
              .set("Type", "Quasi-Newton Method");
          }
        else
          list.sublist("Step").set("Type", "Spectral Gradient");
        list.sublist("Status Test")
          .set("Gradient Tolerance", settings.gradient_tolerance);
        list.sublist("Status Test")
          .set("Step Tolerance", settings.step_tolerance);
        list.sublist("Status Test")
          .set("Iteration Limit", static_cast<int>(settings.max_iterations));
        return list;
      }
    } // namespace


    LocalOptimum
    minimise(OutputObjective            &objective,
             const VectorType           &start,
             const VectorType           &lower,
             const VectorType           &upper,
             const OptimisationSettings &settings)
    {
      const unsigned int n = start.size();
      auto x = ROL::makePtr<Adaptor>(Teuchos::rcp(new VectorType(start)));
      // Clip the start into the box (the previous level's optimum lies in it
      // already; this guards against round-off).
      for (unsigned int i = 0; i < n; ++i)
        unwrap(*x)[i] = std::min(std::max(start[i], lower[i]), upper[i]);

      LocalOptimum optimum;
      bool         degenerate = true;
      for (unsigned int i = 0; i < n; ++i)
        degenerate = degenerate && upper[i] <= lower[i];
      if (!degenerate)
        {
          RolObjective rol_objective(objective);
          auto lo = ROL::makePtr<Adaptor>(Teuchos::rcp(new VectorType(lower)));
          auto hi = ROL::makePtr<Adaptor>(Teuchos::rcp(new VectorType(upper)));
          auto bounds  = ROL::makePtr<ROL::Bounds<double>>(lo, hi);
          auto problem = ROL::makePtr<ROL::Problem<double>>(ROL::makePtrFromRef(
                                                              rol_objective),
                                                            x);
          problem->addBoundConstraint(bounds);
          problem->finalize(false, false);

          ROL::ParameterList  list = rol_parameters(settings);
          ROL::Solver<double> solver(problem, list);
          std::ostringstream  quiet;
          solver.solve(quiet);
          optimum.iterations = solver.getAlgorithmState()->iter;
          optimum.converged =
            solver.getAlgorithmState()->statusFlag != ROL::EXITSTATUS_MAXITER;
        }
      else
        optimum.iterations = 0;

      optimum.x = unwrap(*x);
      for (unsigned int i = 0; i < n; ++i) // ROL keeps x feasible; be exact
        optimum.x[i] = std::min(std::max(optimum.x[i], lower[i]), upper[i]);
      optimum.value = objective.at(optimum.x);
      // (ROL ends where it started if it found no better point with a
      // solution; never worse than its start.)
      VectorType clipped_start(n);
      for (unsigned int i = 0; i < n; ++i)
        clipped_start[i] = std::min(std::max(start[i], lower[i]), upper[i]);
      const double at_start = objective.at(clipped_start);
      if (!(optimum.value <= at_start))
        {
          optimum.x     = clipped_start;
          optimum.value = at_start;
        }
      optimum.gradient.reinit(n);
      objective.gradient_at(optimum.gradient, optimum.x);
      return optimum;
    }
  } // namespace LocalOptimisation
} // namespace FuzzyContact
