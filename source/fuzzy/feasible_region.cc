// The part of each alpha-box where a model has a solution
// (feasible_region.h).

#include <fuzzycontact/fuzzy/feasible_region.h>
#include <fuzzycontact/fuzzy/global_stage.h>
#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <boost/serialization/vector.hpp>

#include <map>

namespace FuzzyContact
{
  using namespace dealii;

  double
  LevelFeasibility::feasible_fraction() const
  {
    return n_design > 0 ? 1. * n_design_feasible / n_design : 1.;
  }


  namespace
  {
    // The feasibility of each distinct point, evaluated once.
    class Memo
    {
    public:
      explicit Memo(const Feasibility &feasible)
          : feasible(feasible)
      {
      }

      bool
      operator()(const std::vector<double> &p)
      {
        const auto found = known.find(p);
        if (found != known.end())
          return found->second;
        return known[p] = feasible(p);
      }

      unsigned long
      size() const
      {
        return known.size();
      }

    private:
      const Feasibility                  &feasible;
      std::map<std::vector<double>, bool> known;
    };

    // The free parameters (a support of non-zero width).
    std::vector<unsigned int>
    free_parameters(const std::vector<FuzzyNumber> &parameters)
    {
      std::vector<unsigned int> free;
      for (unsigned int d = 0; d < parameters.size(); ++d)
        if (parameters[d].alpha_cut(0).width() > 0)
          free.push_back(d);
      return free;
    }

    // Vertex @p corner of the box (bit i: the upper end of free parameter
    // i; crisp ones at the midpoint of their cut).
    std::vector<double>
    vertex(const std::vector<Interval>     &box,
           const std::vector<unsigned int> &free,
           const unsigned long              corner)
    {
      std::vector<double> p;
      for (const Interval &i : box)
        p.push_back(i.midpoint());
      for (unsigned int i = 0; i < free.size(); ++i)
        p[free[i]] =
          (corner >> i) & 1 ? box[free[i]].upper : box[free[i]].lower;
      return p;
    }

    // The first vertex of the box at @p alpha without a solution, as its
    // corner number, or -1.
    long
    infeasible_corner(const std::vector<FuzzyNumber>  &parameters,
                      const std::vector<unsigned int> &free,
                      const double                     alpha,
                      Memo                            &feasible)
    {
      const std::vector<Interval> box = alpha_box(parameters, alpha);
      for (unsigned long c = 0; c < (1ul << free.size()); ++c)
        if (!feasible(vertex(box, free, c)))
          return c;
      return -1;
    }

    // Along the edge of the box from vertex @p from (no solution) to @p to
    // (a solution), which differ in parameter @p d: the point nearest to
    // @p from with a solution, to 1e-10 of the edge, by bisection between
    // the fractions @p out (no solution) and @p in (a solution).
    std::vector<double>
    crossing(const std::vector<double> &from,
             const std::vector<double> &to,
             const unsigned int         d,
             Memo                      &feasible,
             double                     out = 0,
             double                     in  = 1)
    {
      std::vector<double> p = from;
      for (unsigned int i = 0; i < 40 && in - out > 1e-10; ++i)
        {
          const double middle      = 0.5 * (out + in);
          p[d]                     = from[d] + middle * (to[d] - from[d]);
          (feasible(p) ? in : out) = middle;
        }
      p[d] = in == 1 ? to[d] : from[d] + in * (to[d] - from[d]);
      return p;
    }

    // The same with a cheap necessary check: its crossing first, which is
    // the whole check's if the whole check holds there (the part of the
    // edge with a solution of the whole check lies inside the cheap one's);
    // else the whole check's bisection from there on.
    std::vector<double>
    crossing(const std::vector<double> &from,
             const std::vector<double> &to,
             const unsigned int         d,
             Memo                      &feasible,
             Memo                      &necessary)
    {
      const std::vector<double> p = crossing(from, to, d, necessary);
      if (feasible(p))
        return p;
      const double width = to[d] - from[d];
      return crossing(from, to, d, feasible, (p[d] - from[d]) / width, 1);
    }
  } // namespace


  FeasibleRegion
  feasible_region(const std::vector<FuzzyNumber> &parameters,
                  const std::vector<double>      &alpha,
                  const Feasibility              &feasibility,
                  const unsigned int              design_points,
                  const Feasibility              &necessary_check)
  {
    Timer          timer;
    Memo           feasible(feasibility);
    Memo           necessary(necessary_check ? necessary_check : feasibility);
    FeasibleRegion region;
    const std::vector<unsigned int> free = free_parameters(parameters);
    AssertThrow(free.size() < 20,
                ExcMessage("The feasible region is found on the vertices of "
                           "the boxes: at most 19 fuzzy parameters."));
    const std::vector<LocalOptimisation::VectorType> design =
      LocalOptimisation::scrambled_sobol(free.empty() ? 0 : design_points,
                                         free.size(),
                                         20261125);

    // Every level: its vertices, its design points, and where the edges
    // from a vertex without a solution find one.
    for (const double a : alpha)
      {
        LevelFeasibility            level;
        const std::vector<Interval> box = alpha_box(parameters, a);
        level.alpha                     = a;
        bool point                      = true;
        for (const unsigned int d : free)
          point = point && box[d].width() == 0;
        const unsigned long n_corners = point ? 1 : 1ul << free.size();
        long                first     = -1;
        // A vertex the whole check refused and the cheap one accepted:
        // the design points need the whole check too.
        bool whole = !necessary_check;
        for (unsigned long c = 0; c < n_corners; ++c)
          {
            const bool ok = feasible(vertex(box, free, c));
            ++level.n_vertices;
            level.n_vertices_feasible += ok;
            if (!ok && first < 0)
              first = c;
            if (!ok && !whole)
              whole = necessary(vertex(box, free, c));
          }
        if (!point)
          for (const auto &u : design)
            {
              std::vector<double> p = vertex(box, free, 0);
              for (unsigned int i = 0; i < free.size(); ++i)
                p[free[i]] = box[free[i]].lower + u[i] * box[free[i]].width();
              ++level.n_design;
              level.n_design_feasible += whole ? feasible(p) : necessary(p);
            }
        level.possible = first >= 0 || level.n_design_feasible < level.n_design;
        if (first < 0 && level.possible)
          region.vertices_decide = false;
        if (first >= 0)
          {
            level.vertex = vertex(box, free, first);
            if (!point)
              for (unsigned int i = 0; i < free.size(); ++i)
                {
                  const std::vector<double> neighbour =
                    vertex(box, free, first ^ (1ul << i));
                  if (feasible(neighbour))
                    level.boundary.push_back({free[i],
                                              crossing(level.vertex,
                                                       neighbour,
                                                       free[i],
                                                       feasible,
                                                       necessary)});
                }
          }
        region.possible = region.possible || level.possible;
        region.levels.push_back(level);
      }

    // The membership: the largest alpha whose box has a vertex without a
    // solution, by bisection between the support and the core.
    if (infeasible_corner(parameters, free, 1., feasible) >= 0)
      {
        region.membership = 1;
        region.starts_at =
          vertex(alpha_box(parameters, 1.),
                 free,
                 infeasible_corner(parameters, free, 1., feasible));
      }
    else if (infeasible_corner(parameters, free, 0., feasible) >= 0)
      {
        // The cheap check's membership first (every box with a vertex
        // without its solution has one without the whole check's), then
        // the whole check's above it.
        double with = 0, without = 1;
        if (necessary_check &&
            infeasible_corner(parameters, free, 0., necessary) >= 0)
          {
            for (unsigned int i = 0; i < 60 && without - with > 1e-12; ++i)
              {
                const double middle = 0.5 * (with + without);
                (infeasible_corner(parameters, free, middle, necessary) >= 0
                   ? with
                   : without)       = middle;
              }
            // (The boxes shrink as alpha grows: if the whole check holds
            // at every vertex there, its membership lies in [with,
            // without] too.)
            if (infeasible_corner(parameters, free, without, feasible) >= 0)
              {
                with    = without;
                without = 1;
              }
          }
        for (unsigned int i = 0; i < 60 && without - with > 1e-12; ++i)
          {
            const double middle = 0.5 * (with + without);
            (infeasible_corner(parameters, free, middle, feasible) >= 0
               ? with
               : without)       = middle;
          }
        region.membership = without;
        region.starts_at =
          vertex(alpha_box(parameters, without),
                 free,
                 infeasible_corner(parameters, free, with, feasible));
      }
    // Where the vertices did not decide, the levels' own findings.
    for (const LevelFeasibility &level : region.levels)
      if (level.possible && level.alpha > region.membership)
        {
          region.membership = level.alpha;
          region.starts_at.clear();
        }
    region.n_evaluations =
      feasible.size() + (necessary_check ? necessary.size() : 0);
    region.wall_time = timer.wall_time();
    return region;
  }


  FeasibleRegion
  feasible_region_on_ranks(const std::vector<FuzzyNumber> &parameters,
                           const std::vector<double>      &alpha,
                           const Feasibility              &feasible,
                           const unsigned int              design_points,
                           const MPI_Comm                  comm,
                           const MPI_Comm                  solving,
                           const Feasibility              &necessary)
  {
    const bool parallel = Utilities::MPI::job_supports_mpi() &&
                          Utilities::MPI::n_mpi_processes(comm) > 1;
    if (!parallel)
      return feasible_region(parameters,
                             alpha,
                             feasible,
                             design_points,
                             necessary);
    // The lowest rank of @p comm among the solving ones sends the result.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int root =
      Utilities::MPI::min(solving != MPI_COMM_NULL ? rank : n_ranks, comm);
    AssertThrow(root < n_ranks,
                ExcMessage("No MPI rank can evaluate the feasibility."));
    FeasibleRegion region;
    if (solving != MPI_COMM_NULL)
      region =
        feasible_region(parameters, alpha, feasible, design_points, necessary);
    return Utilities::MPI::broadcast(comm, region, root);
  }
} // namespace FuzzyContact
