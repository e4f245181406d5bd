// The optimisation method of interval_analysis.h, on Trilinos ROL through
// deal.II's ROL vector adaptor. Kept in a translation unit of its own because
// ROL's headers are heavy.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/interval_analysis.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>
#include <deal.II/optimization/rol/vector_adaptor.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <ROL_Bounds.hpp>
#include <ROL_Objective.hpp>
#include <ROL_Problem.hpp>
#include <ROL_Solver.hpp>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  void
  OptimisationSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Optimisation");
    prm.declare_entry("algorithm",
                      "spectral gradient",
                      Patterns::Selection("spectral gradient|quasi-newton"),
                      "ROL's bound-constrained algorithm: projected spectral "
                      "gradient (Barzilai-Borwein steps) or a projected "
                      "quasi-Newton (L-BFGS) line search.");
    prm.declare_entry("gradient tolerance",
                      "1e-10",
                      Patterns::Double(),
                      "ROL's tolerance on the projected gradient of the "
                      "scaled objective S / |S(nominal)|.");
    prm.declare_entry("step tolerance",
                      "1e-12",
                      Patterns::Double(),
                      "ROL's tolerance on the step in normalised parameters.");
    prm.declare_entry("iteration limit",
                      "50",
                      Patterns::Integer(),
                      "ROL iterations per output, bound and alpha level.");
    prm.declare_entry("finite difference step",
                      "1e-4",
                      Patterns::Double(),
                      "Step of the finite-difference sensitivities, relative "
                      "to the width of each parameter's support.");
    prm.declare_entry("interior tolerance",
                      "1e-6",
                      Patterns::Double(),
                      "An optimum further than this (relative to the "
                      "alpha-cut width) from both ends of a parameter's "
                      "interval counts as interior.");
    prm.declare_entry("response tolerance",
                      "1e-7",
                      Patterns::Double(),
                      "Relative accuracy of the model's outputs (the FL2C "
                      "tolerance makes them accurate to about that much): "
                      "smaller differences are no evidence of a non-monotone "
                      "response. Keep the finite difference step well above "
                      "it.");
    prm.declare_entry("multi-start fallback",
                      "true",
                      Patterns::Bool(),
                      "On a detected non-monotone response, restart the "
                      "local optimisation from every vertex and the centre.");
    prm.leave_subsection();
  }


  void
  OptimisationSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Optimisation");
    algorithm          = prm.get("algorithm");
    gradient_tolerance = Input::positive(prm.get_double("gradient tolerance"),
                                         "Optimisation: gradient tolerance");
    step_tolerance     = Input::positive(prm.get_double("step tolerance"),
                                     "Optimisation: step tolerance");
    const long iterations = prm.get_integer("iteration limit");
    AssertThrow(iterations >= 1,
                ExcMessage("Optimisation: iteration limit must be at least "
                           "1."));
    max_iterations = iterations;
    finite_difference_step =
      Input::positive(prm.get_double("finite difference step"),
                      "Optimisation: finite difference "
                      "step");
    AssertThrow(finite_difference_step < 0.1,
                ExcMessage("Optimisation: finite difference step must be "
                           "below 0.1 (it is relative to the support width)."));
    interior_tolerance = Input::positive(prm.get_double("interior tolerance"),
                                         "Optimisation: interior tolerance");
    response_tolerance = Input::positive(prm.get_double("response tolerance"),
                                         "Optimisation: response tolerance");
    AssertThrow(finite_difference_step > 10 * response_tolerance,
                ExcMessage("Optimisation: the finite difference step must be "
                           "well above the response tolerance (10 times at "
                           "least), or the sensitivities are noise."));
    fallback = prm.get_bool("multi-start fallback");
    prm.leave_subsection();
  }


  namespace
  {
    using VectorType = Vector<double>;
    using Adaptor    = Rol::VectorAdaptor<VectorType>;

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

    // The uncertain parameters (those with a support of non-zero width) in
    // coordinates normalised by their support: x = (p - a) / (b - a).
    class Normalisation
    {
    public:
      explicit Normalisation(const std::vector<FuzzyNumber> &parameters)
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
      n_free() const
      {
        return free.size();
      }

      std::vector<double>
      parameters(const VectorType &x) const
      {
        std::vector<double> p = fixed;
        for (unsigned int i = 0; i < free.size(); ++i)
          {
            const Interval &s = supports[free[i]];
            // The ends are returned exactly, so that vertices coincide with
            // those of the vertex method and of the cache.
            p[free[i]] = x[i] <= 0   ? s.lower
                         : x[i] >= 1 ? s.upper
                                     : s.lower + x[i] * s.width();
          }
        return p;
      }

      double
      coordinate(const unsigned int i, const double p) const
      {
        const Interval &s = supports[free[i]];
        if (p == s.lower)
          return 0;
        if (p == s.upper)
          return 1;
        return (p - s.lower) / s.width();
      }

      // The box of a level in normalised coordinates.
      std::pair<VectorType, VectorType>
      box(const std::vector<FuzzyNumber> &parameters, const double alpha) const
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

      std::vector<unsigned int> free;
      std::vector<Interval>     supports;
      std::vector<double>       fixed;
    };

    // sign * S_k(p(x)) / scale, with central finite-difference gradients
    // (one-sided where a central step would leave the level's box).
    class OutputObjective : public ROL::Objective<double>
    {
    public:
      OutputObjective(EvaluationCache     &cache,
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
      at(const VectorType &x)
      {
        const std::vector<double> &s = cache(normalisation.parameters(x));
        AssertThrow(std::isfinite(s[output]),
                    ExcMessage("The response returned a non-finite value."));
        return sign * s[output] / scale;
      }

      double
      value(const ROL::Vector<double> &x, double & /*tol*/) override
      {
        return at(unwrap(x));
      }

      void
      gradient(ROL::Vector<double>       &g,
               const ROL::Vector<double> &x,
               double & /*tol*/) override
      {
        VectorType       &grad = unwrap(g);
        const VectorType &x0   = unwrap(x);
        gradient_at(grad, x0);
      }

      void
      gradient_at(VectorType &grad, const VectorType &x0)
      {
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
            grad[i]         = (fp - fm) / (up - down);
          }
      }

    private:
      EvaluationCache     &cache;
      const Normalisation &normalisation;
      const unsigned int   output;
      const double         sign;
      const double         scale;
      const double         step;
      const VectorType    &lower;
      const VectorType    &upper;
    };

    struct LocalOptimum
    {
      VectorType x;
      double     value; // of the scaled, signed objective
      VectorType gradient;
      int        iterations;
      // ROL's exit: false if it stopped at its iteration limit.
      bool converged = true;
    };

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
          auto lo = ROL::makePtr<Adaptor>(Teuchos::rcp(new VectorType(lower)));
          auto hi = ROL::makePtr<Adaptor>(Teuchos::rcp(new VectorType(upper)));
          auto bounds = ROL::makePtr<ROL::Bounds<double>>(lo, hi);
          auto problem =
            ROL::makePtr<ROL::Problem<double>>(ROL::makePtrFromRef(objective),
                                               x);
          problem->addBoundConstraint(bounds);
          problem->finalize(false, false);

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
      optimum.gradient.reinit(n);
      objective.gradient_at(optimum.gradient, optimum.x);
      return optimum;
    }

    std::string
    format(const double x)
    {
      std::ostringstream s;
      s.precision(6);
      s << x;
      return s.str();
    }

    // The result of one chain: one output, one direction, all levels.
    struct ChainResult
    {
      std::vector<double>              value;    // per level, unscaled
      std::vector<std::vector<double>> argument; // per level, all parameters
      std::vector<std::string>         notes;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &value &argument &notes;
      }
    };
  } // namespace


  FuzzyOutputBounds
  optimisation_method(const std::vector<FuzzyNumber> &parameters,
                      const std::vector<double>      &alpha,
                      const Response                 &response,
                      const std::vector<std::string> &output_names,
                      const OptimisationSettings     &settings,
                      const MPI_Comm                  comm)
  {
    Timer              timer;
    const unsigned int n_outputs = output_names.size();
    const bool         parallel  = Utilities::MPI::job_supports_mpi() &&
                          Utilities::MPI::n_mpi_processes(comm) > 1;
    const unsigned int n_ranks =
      parallel ? Utilities::MPI::n_mpi_processes(comm) : 1;
    const unsigned int rank =
      parallel ? Utilities::MPI::this_mpi_process(comm) : 0;

    EvaluationCache     cache(response);
    const Normalisation normalisation(parameters);
    const unsigned int  n = normalisation.n_free();

    // Levels from the core (alpha = 1) down to the support.
    std::vector<unsigned int> order(alpha.size());
    for (unsigned int l = 0; l < alpha.size(); ++l)
      order[l] = l;
    std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
      return alpha[a] > alpha[b];
    });

    // The nominal point: centre of the core.
    VectorType centre(n);
    {
      const auto [lo, hi] = normalisation.box(parameters, 1.0);
      for (unsigned int i = 0; i < n; ++i)
        centre[i] = 0.5 * (lo[i] + hi[i]);
    }
    const std::vector<double> nominal = cache(normalisation.parameters(centre));
    AssertThrow(nominal.size() == n_outputs,
                ExcMessage(
                  "The response returned " + std::to_string(nominal.size()) +
                  " outputs instead of " + std::to_string(n_outputs) + "."));

    // One chain per output and direction; chains are dealt to the ranks.
    std::vector<std::pair<unsigned int, ChainResult>> mine;
    for (unsigned int chain = rank; chain < 2 * n_outputs; chain += n_ranks)
      {
        const unsigned int k     = chain / 2;
        const bool         upper = chain % 2;
        const double       sign  = upper ? -1. : 1.;
        const double       scale =
          std::abs(nominal[k]) > 0 ? std::abs(nominal[k]) : 1.;
        const std::string what =
          output_names[k] + (upper ? " (upper bound)" : " (lower bound)");

        ChainResult result;
        result.value.resize(alpha.size());
        result.argument.resize(alpha.size());
        VectorType              start = centre;
        std::vector<VectorType> gradients;
        for (const unsigned int l : order)
          {
            const auto [lo, hi] = normalisation.box(parameters, alpha[l]);
            OutputObjective objective(cache,
                                      normalisation,
                                      k,
                                      sign,
                                      scale,
                                      settings.finite_difference_step,
                                      lo,
                                      hi);
            LocalOptimum    best = minimise(objective, start, lo, hi, settings);

            // Is the response monotone here? An interior optimum, or a
            // vertex better than the local optimum, says it is not.
            // A coordinate strictly inside its interval, compared with the two
            // ends of the interval (the other coordinates kept):
            //  - both ends worse: an interior optimum (non-monotone response);
            //  - both ends better: an interior stationary point that is no
            //    optimum (non-monotone response); move to the better end;
            //  - one end better: the optimiser stopped short in a monotone
            //    direction; move there and say so;
            //  - an end as good: the response is flat in that parameter (it
            //    does not depend on it there); move there.
            std::vector<std::string> findings;
            const double             noise =
              settings.response_tolerance * std::max(1., std::abs(best.value));
            bool moved = false;
            for (unsigned int i = 0; i < n; ++i)
              {
                const double width = hi[i] - lo[i];
                if (width <= 0)
                  continue;
                const double tol = settings.interior_tolerance * width;
                if (best.x[i] <= lo[i] + tol || best.x[i] >= hi[i] - tol)
                  continue;
                VectorType at_end      = best.x;
                at_end[i]              = lo[i];
                const double f_lo      = objective.at(at_end);
                at_end[i]              = hi[i];
                const double      f_hi = objective.at(at_end);
                const std::string where =
                  "parameter " + std::to_string(normalisation.free[i] + 1) +
                  " (at " +
                  format(
                    normalisation.parameters(best.x)[normalisation.free[i]]) +
                  ")";
                const bool lo_better = f_lo < best.value - noise;
                const bool hi_better = f_hi < best.value - noise;
                if (std::min(f_lo, f_hi) > best.value + noise)
                  {
                    findings.push_back("optimum inside the interval of " +
                                       where);
                    continue;
                  }
                if (lo_better && hi_better)
                  findings.push_back("a stationary point inside the interval "
                                     "of " +
                                     where + " that is no optimum");
                else
                  moved = moved || lo_better || hi_better;
                best.x[i]  = f_lo <= f_hi ? lo[i] : hi[i];
                best.value = std::min(best.value, std::min(f_lo, f_hi));
              }
            double best_vertex = std::numeric_limits<double>::infinity();
            if (n > 0 && n < 20)
              for (unsigned long corner = 0; corner < (1ul << n); ++corner)
                {
                  VectorType v(n);
                  for (unsigned int i = 0; i < n; ++i)
                    v[i] = (corner >> i) & 1 ? hi[i] : lo[i];
                  best_vertex = std::min(best_vertex, objective.at(v));
                }
            if (best_vertex < best.value - settings.response_tolerance *
                                             std::max(1., std::abs(best.value)))
              findings.push_back("a vertex of the box is better than the "
                                 "local optimum");
            gradients.push_back(best.gradient);

            if (!findings.empty())
              {
                std::string note = what + ", alpha = " + format(alpha[l]) +
                                   ": non-monotone response (";
                for (unsigned int f = 0; f < findings.size(); ++f)
                  note += (f ? "; " : "") + findings[f];
                note += ")";
                if (settings.fallback)
                  {
                    // Multi-start from every vertex and the centre.
                    std::vector<VectorType> starts;
                    for (unsigned long corner = 0;
                         n < 20 && corner < (1ul << n);
                         ++corner)
                      {
                        VectorType v(n);
                        for (unsigned int i = 0; i < n; ++i)
                          v[i] = (corner >> i) & 1 ? hi[i] : lo[i];
                        starts.push_back(v);
                      }
                    VectorType mid(n);
                    for (unsigned int i = 0; i < n; ++i)
                      mid[i] = 0.5 * (lo[i] + hi[i]);
                    starts.push_back(mid);
                    const double before = best.value;
                    for (const VectorType &s : starts)
                      {
                        LocalOptimum candidate =
                          minimise(objective, s, lo, hi, settings);
                        if (candidate.value < best.value)
                          best = candidate;
                      }
                    note +=
                      "; fallback: multi-start from " +
                      std::to_string(starts.size()) +
                      " points (vertices and centre)" +
                      (best.value < before ? ", which improved the "
                                             "bound to " +
                                               format(sign * best.value * scale)
                                           : ", which confirmed it");
                  }
                else
                  note += "; no fallback (disabled)";
                result.notes.push_back(note);
              }

            if (moved || !best.converged)
              result.notes.push_back(
                what + ", alpha = " + format(alpha[l]) +
                ": the local optimiser stopped short of the optimum (" +
                (best.converged ? "converged to its tolerances"
                                : "at its iteration limit") +
                "); the ends of the parameter intervals were better and the "
                "optimum was moved there");
            result.value[l]    = sign * best.value * scale;
            result.argument[l] = normalisation.parameters(best.x);
            start              = best.x;
          }

        // A sensitivity that changes sign between the optima of the levels.
        for (unsigned int i = 0; i < n; ++i)
          {
            bool positive = false, negative = false;
            for (const VectorType &g : gradients)
              {
                // A gradient below the noise of a finite difference of the
                // response carries no sign.
                const double noise = 10 * settings.response_tolerance /
                                     settings.finite_difference_step;
                positive = positive || g[i] > noise;
                negative = negative || g[i] < -noise;
              }
            if (positive && negative)
              result.notes.push_back(
                what + ": the sensitivity to parameter " +
                std::to_string(normalisation.free[i] + 1) +
                " changes sign between alpha levels (non-monotone response)");
          }
        mine.emplace_back(chain, std::move(result));
      }

    // Gather the chains of all ranks.
    std::vector<std::pair<unsigned int, ChainResult>> all = mine;
    unsigned long n_evaluations = cache.n_evaluations();
    double        wall_time     = timer.wall_time();
    if (parallel)
      {
        all.clear();
        for (auto &part : Utilities::MPI::all_gather(comm, mine))
          for (auto &c : part)
            all.push_back(std::move(c));
        n_evaluations = Utilities::MPI::sum(n_evaluations, comm);
        wall_time     = Utilities::MPI::max(wall_time, comm);
      }
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });

    FuzzyOutputBounds result;
    result.alpha = alpha;
    result.bounds.assign(n_outputs, std::vector<Interval>(alpha.size()));
    result.argmin.assign(n_outputs,
                         std::vector<std::vector<double>>(alpha.size()));
    result.argmax = result.argmin;
    for (const auto &[chain, r] : all)
      {
        const unsigned int k = chain / 2;
        for (unsigned int l = 0; l < alpha.size(); ++l)
          if (chain % 2)
            {
              result.bounds[k][l].upper = r.value[l];
              result.argmax[k][l]       = r.argument[l];
            }
          else
            {
              result.bounds[k][l].lower = r.value[l];
              result.argmin[k][l]       = r.argument[l];
            }
        for (const std::string &note : r.notes)
          result.notes.push_back(note);
      }
    result.n_evaluations = n_evaluations;
    result.wall_time     = wall_time;
    return result;
  }
} // namespace FuzzyContact
