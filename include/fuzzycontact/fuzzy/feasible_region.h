// The part of each alpha-box where a model has a solution, for models that
// have none at some parameter values: a body held by contact alone slides
// where no contact forces in the friction cones can hold its load (a low
// friction coefficient, a large push), and the static problem has no
// solution there (contact/contact_problem.h).
//
// For every level it says whether some point of the box has no solution,
// how large a share of the box has one (the share of a scrambled Sobol
// design's points, global_stage.h), and where along the box's edges the
// solution is lost (bisection from a vertex without a solution towards
// each neighbour with one). Over the levels this is a fuzzy statement,
// "a point without solution is possible", whose membership is the largest
// alpha whose box holds such a point: found by bisection in alpha on the
// vertices of the boxes, with the vertex at which it starts.
//
// The vertices decide exactly when a box lies in the set with a solution as
// soon as its vertices do. That holds for the statics of bodies held by
// contact alone: the load resultants that admissible contact forces
// balance form a convex cone, the loads (and, under gravity, the
// densities) enter the resultant linearly, a larger friction coefficient
// only widens the cones, and moduli and gaps do not enter at all. The
// design's points check it at every level: a design point without a
// solution in a box whose vertices all have one says that they do not
// decide (then the levels' own findings count, and the report says so).
//
// The check may come in two parts: a cheap necessary one (for contact, an
// NNLS problem on the cones' edges, no contact solve) and the whole one
// (for contact, also a solve that stays within small sliding,
// contact/small_sliding.h). The vertices and the bisections use the whole
// check; the design points the cheap one, unless the whole check refused
// a vertex of the level that the cheap one accepted (then the whole one
// too, so that the share with a solution is that of the whole check). It
// runs on every rank that can evaluate it, each the same points, and
// feasible_region_on_ranks() sends the result to the others.

#ifndef fuzzycontact_fuzzy_feasible_region_h
#define fuzzycontact_fuzzy_feasible_region_h

#include <fuzzycontact/fuzzy/fuzzy_number.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <vector>

namespace FuzzyContact
{
  /** Whether a model has a solution at the parameter values given. */
  using Feasibility = std::function<bool(const std::vector<double> &)>;

  /** Where the solution is lost along an edge of a box. */
  struct BoundaryCrossing
  {
    /** The parameter that varies along the edge (index among all). */
    unsigned int parameter = 0;
    /**
     * The point of the edge nearest to the vertex without a solution that
     * still has one (to 1e-10 of the edge), all parameters.
     */
    std::vector<double> point;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &parameter &point;
    }
  };

  /** The part of one level's box with a solution. */
  struct LevelFeasibility
  {
    double alpha = 0;
    /** Some vertex or design point of the box has no solution. */
    bool possible = false;
    /** The box's vertices, and those with a solution. */
    unsigned long n_vertices = 0, n_vertices_feasible = 0;
    /**
     * The design's points in the box, and those with a solution: their
     * ratio estimates the share of the box's volume with a solution.
     */
    unsigned long n_design = 0, n_design_feasible = 0;
    /** A vertex without a solution (empty if every vertex has one). */
    std::vector<double> vertex;
    /** Along the box's edges from that vertex, where a solution starts. */
    std::vector<BoundaryCrossing> boundary;

    /** n_design_feasible / n_design (1 without design points). */
    double
    feasible_fraction() const;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &alpha &possible &n_vertices &n_vertices_feasible &n_design
        &n_design_feasible &vertex &boundary;
    }
  };

  /** The part of every level's box with a solution. */
  struct FeasibleRegion
  {
    std::vector<LevelFeasibility> levels;
    /** Some point of the support's box has no solution. */
    bool possible = false;
    /**
     * The membership of "a point without a solution is possible": the
     * largest alpha whose box holds one (to 1e-10; 1 if the core does; 0
     * and possible = false if no box does).
     */
    double membership = 0;
    /**
     * Where it starts: the vertex of the box at alpha = membership whose
     * neighbours in alpha just below have no solution (empty if none).
     */
    std::vector<double> starts_at;
    /** False if a design point showed what the vertices did not. */
    bool vertices_decide = true;
    /** Evaluations of the feasibility, and its wall time [s]. */
    unsigned long n_evaluations = 0;
    double        wall_time     = 0;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &levels &possible &membership &starts_at &vertices_decide
        &n_evaluations &wall_time;
    }
  };

  /**
   * The part of the boxes of the levels @p alpha of @p parameters where
   * @p feasible holds (see the top of this file), with @p design_points
   * scrambled Sobol points per box; @p necessary (if given) is a cheap
   * check that holds wherever @p feasible does.
   */
  FeasibleRegion
  feasible_region(const std::vector<FuzzyNumber> &parameters,
                  const std::vector<double>      &alpha,
                  const Feasibility              &feasible,
                  const unsigned int              design_points,
                  const Feasibility              &necessary = {});

  /**
   * feasible_region() computed on the ranks of @p comm where @p solving is
   * not MPI_COMM_NULL (they can evaluate @p feasible; each computes the
   * same) and sent to every rank of @p comm. Collective on @p comm.
   */
  FeasibleRegion
  feasible_region_on_ranks(const std::vector<FuzzyNumber> &parameters,
                           const std::vector<double>      &alpha,
                           const Feasibility              &feasible,
                           const unsigned int              design_points,
                           const MPI_Comm                  comm,
                           const MPI_Comm                  solving,
                           const Feasibility              &necessary = {});
} // namespace FuzzyContact

#endif
