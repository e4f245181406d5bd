// The global stage and the refinement of the optimisation method
// (global_stage.h).

#include <fuzzycontact/fuzzy/global_stage.h>

#include <boost/random/sobol.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    std::vector<VectorType>
    scrambled_sobol(const unsigned int n_points,
                    const unsigned int dimension,
                    const unsigned int seed)
    {
      std::vector<VectorType> design(n_points, VectorType(dimension));
      if (n_points == 0 || dimension == 0)
        return design;
      // The Sobol points as 32-bit integers: index 0 (the origin, which
      // Boost's engine skips) and then the engine's, in Gray-code order
      // (the first 2^m of them are the same set as in natural order).
      using Engine = boost::random::sobol_engine<std::uint32_t, 32>;
      Engine                                  sobol(dimension);
      std::vector<std::vector<std::uint32_t>> bits(
        n_points,
        std::vector<std::uint32_t>(dimension, 0u));
      for (unsigned int i = 1; i < n_points; ++i)
        for (unsigned int d = 0; d < dimension; ++d)
          bits[i][d] = sobol();
      // Matousek's linear scrambling and a digital shift per coordinate:
      // output bit k (k = 0 the most significant) is the parity of the
      // input bits masked by row k of a random lower triangular matrix
      // with unit diagonal, then XOR a random shift. std::mt19937's
      // sequence is fixed by the standard.
      std::mt19937 random(seed);
      for (unsigned int d = 0; d < dimension; ++d)
        {
          std::array<std::uint32_t, 32> row;
          for (unsigned int k = 0; k < 32; ++k)
            {
              // bit (31 - k) is the k-th most significant
              const std::uint32_t diagonal = 1u << (31 - k);
              const std::uint32_t above =
                k == 0 ? 0u : ~((diagonal << 1) - 1u); // more significant
              row[k] =
                diagonal | (static_cast<std::uint32_t>(random()) & above);
            }
          const std::uint32_t shift = static_cast<std::uint32_t>(random());
          for (unsigned int i = 0; i < n_points; ++i)
            {
              const std::uint32_t x = bits[i][d];
              std::uint32_t       y = 0;
              for (unsigned int k = 0; k < 32; ++k)
                if (__builtin_parity(x & row[k]))
                  y |= 1u << (31 - k);
              design[i][d] = ((y ^ shift) + 0.5) / 4294967296.;
            }
        }
      return design;
    }


    unsigned int
    default_design_points(const unsigned int n_free)
    {
      unsigned int n = 32;
      while (n < 32 * n_free)
        n *= 2;
      return n;
    }


    namespace
    {
      bool
      is_point(const VectorType &lower, const VectorType &upper)
      {
        for (unsigned int i = 0; i < lower.size(); ++i)
          if (upper[i] > lower[i])
            return false;
        return true;
      }

      VectorType
      clipped(const VectorType &x,
              const VectorType &lower,
              const VectorType &upper)
      {
        VectorType y(x.size());
        for (unsigned int i = 0; i < x.size(); ++i)
          y[i] = std::min(std::max(x[i], lower[i]), upper[i]);
        return y;
      }

      // The first @p n_vertices of fixed_points() are the vertices.
      unsigned long
      n_vertices(const VectorType &lower)
      {
        const unsigned int n = lower.size();
        return n > 0 && n < 20 ? 1ul << n : 0;
      }
    } // namespace


    std::vector<VectorType>
    fixed_points(const std::vector<VectorType> &unit_design,
                 const VectorType              &lower,
                 const VectorType              &upper)
    {
      const unsigned int      n = lower.size();
      std::vector<VectorType> points;
      for (unsigned long corner = 0; corner < n_vertices(lower); ++corner)
        {
          VectorType v(n);
          for (unsigned int i = 0; i < n; ++i)
            v[i] = (corner >> i) & 1 ? upper[i] : lower[i];
          points.push_back(clipped(v, lower, upper));
        }
      if (!is_point(lower, upper))
        for (const VectorType &u : unit_design)
          {
            VectorType x(n);
            for (unsigned int i = 0; i < n; ++i)
              x[i] = lower[i] + u[i] * (upper[i] - lower[i]);
            points.push_back(clipped(x, lower, upper));
          }
      return points;
    }


    GlobalStage
    global_stage(OutputObjective               &objective,
                 const std::vector<VectorType> &unit_design,
                 const std::vector<VectorType> &seeds,
                 const VectorType              &lower,
                 const VectorType              &upper)
    {
      const bool                               point = is_point(lower, upper);
      std::map<std::vector<double>, Candidate> unique;
      GlobalStage                              stage;
      const auto add = [&](const VectorType &x, const bool vertex) {
        const VectorType          y = clipped(x, lower, upper);
        const std::vector<double> key(y.begin(), y.end());
        if (unique.count(key) == 0)
          unique[key] = Candidate{y, objective.at(y), vertex || point};
      };
      // The vertices, the seeds, the design (a point that is more than one
      // of them counts as the first).
      const std::vector<VectorType> fixed =
        fixed_points(unit_design, lower, upper);
      const unsigned long vertices = n_vertices(lower);
      for (unsigned long i = 0; i < vertices; ++i)
        add(fixed[i], true);
      for (const VectorType &s : seeds)
        add(s, false);
      for (unsigned long i = vertices; i < fixed.size(); ++i)
        add(fixed[i], false);
      stage.n_points = unique.size();
      for (auto &entry : unique)
        if (std::isfinite(entry.second.value))
          stage.candidates.push_back(std::move(entry.second));
      stage.n_infeasible = stage.n_points - stage.candidates.size();
      // Best first; ties keep the order of the coordinates (deterministic).
      std::stable_sort(stage.candidates.begin(),
                       stage.candidates.end(),
                       [](const Candidate &a, const Candidate &b) {
                         return a.value < b.value;
                       });
      return stage;
    }


    std::vector<unsigned int>
    nearest_better_roots(const std::vector<Candidate> &candidates,
                         const VectorType             &lower,
                         const VectorType             &upper,
                         const double                  phi)
    {
      const unsigned int n = candidates.size();
      if (n == 0)
        return {};
      // Distances in units of the box's widths (fixed coordinates aside).
      const auto distance = [&](const VectorType &a, const VectorType &b) {
        double d2 = 0;
        for (unsigned int i = 0; i < a.size(); ++i)
          {
            const double w = upper[i] - lower[i];
            if (w > 0)
              d2 += (a[i] - b[i]) * (a[i] - b[i]) / (w * w);
          }
        return std::sqrt(d2);
      };
      // Candidate i's better ones are those before it (best first, ties
      // in a fixed order).
      std::vector<double> join(n, 0.);
      double              sum = 0;
      for (unsigned int i = 1; i < n; ++i)
        {
          double nearest = std::numeric_limits<double>::infinity();
          for (unsigned int j = 0; j < i; ++j)
            nearest =
              std::min(nearest, distance(candidates[i].x, candidates[j].x));
          join[i] = nearest;
          sum += nearest;
        }
      std::vector<unsigned int> roots{0};
      if (n < 2)
        return roots;
      const double mean = sum / (n - 1);
      for (unsigned int i = 1; i < n; ++i)
        if (join[i] > phi * mean)
          roots.push_back(i);
      return roots;
    }


    bool
    separated(OutputObjective &objective,
              const Candidate &a,
              const Candidate &b,
              const double     noise)
    {
      std::vector<VectorType> between;
      for (const double t : {0.25, 0.5, 0.75})
        {
          VectorType x = a.x;
          x.sadd(1 - t, t, b.x);
          between.push_back(x);
        }
      objective.prefetch(between);
      const double worse = std::max(a.value, b.value) + noise;
      for (const VectorType &x : between)
        if (!(objective.at(x) <= worse)) // (no solution: infinitely worse)
          return true;
      return false;
    }


    Starts
    basin_starts(OutputObjective              &objective,
                 const std::vector<Candidate> &candidates,
                 const VectorType             &lower,
                 const VectorType             &upper,
                 const unsigned int            max_starts,
                 const double                  noise)
    {
      Starts starts;
      if (candidates.empty())
        return starts;
      // A design whose values all lie within the response's accuracy of
      // each other (an output the parameters cannot change: a total force
      // held by statics) shows one basin: the order of its values, on
      // which the clustering rests, is round-off.
      if (candidates.back().value - candidates.front().value <= noise)
        {
          starts.n_roots = 1;
          starts.points.push_back(candidates.front());
          return starts;
        }
      const std::vector<unsigned int> roots =
        nearest_better_roots(candidates, lower, upper);
      starts.n_roots = roots.size();
      starts.points.push_back(candidates[roots[0]]);
      const unsigned int n_tested =
        std::min<unsigned int>(roots.size(), 2 * max_starts + 2);
      unsigned int r = 1;
      for (; r < n_tested && starts.points.size() < max_starts; ++r)
        {
          const Candidate &c        = candidates[roots[r]];
          bool             distinct = true;
          for (const Candidate &s : starts.points)
            distinct = distinct && separated(objective, c, s, noise);
          if (distinct)
            starts.points.push_back(c);
        }
      starts.all_roots_tested = r >= roots.size();
      return starts;
    }


    namespace
    {
      // A poll direction: (coordinate, component) pairs, in units of the
      // widths.
      using Direction = std::vector<std::pair<unsigned int, double>>;

      std::vector<unsigned int>
      free_coordinates(const VectorType &lower, const VectorType &upper)
      {
        std::vector<unsigned int> free;
        for (unsigned int i = 0; i < lower.size(); ++i)
          if (upper[i] > lower[i])
            free.push_back(i);
        return free;
      }

      // The fixed poll directions: +-e_i and, for up to four coordinates
      // that can move, +-e_i +- e_j.
      std::vector<Direction>
      poll_directions(const std::vector<unsigned int> &free)
      {
        std::vector<Direction> directions;
        for (const unsigned int i : free)
          for (const double s : {1., -1.})
            directions.push_back({{i, s}});
        if (free.size() <= 4)
          for (unsigned int a = 0; a < free.size(); ++a)
            for (unsigned int b = a + 1; b < free.size(); ++b)
              for (const double s : {1., -1.})
                for (const double t : {1., -1.})
                  directions.push_back({{free[a], s}, {free[b], t}});
        return directions;
      }

      // The radical inverse of @p index in base @p base (Halton).
      double
      radical_inverse(unsigned long index, const unsigned int base)
      {
        double result = 0, scale = 1. / base;
        for (; index > 0; index /= base, scale /= base)
          result += (index % base) * scale;
        return result;
      }

      // +- the columns of the Householder matrix I - 2 v v^T / |v|^2 of the
      // @p index-th Halton point v (coordinates in [-1, 1]) over the free
      // coordinates: an orthogonal basis turned from poll to poll, as the
      // OrthoMADS directions (Abramson, Audet, Dennis and Le Digabel, SIAM
      // J. Optim. 20, 2009), so that the directions polled become dense.
      std::vector<Direction>
      turned_directions(const std::vector<unsigned int> &free,
                        const unsigned long              index)
      {
        static const unsigned int primes[] =
          {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43};
        const unsigned int     n = free.size();
        std::vector<Direction> directions;
        if (n < 2 || n > sizeof(primes) / sizeof(primes[0]))
          return directions;
        std::vector<double> v(n);
        double              norm2 = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            v[i] = 2 * radical_inverse(index, primes[i]) - 1;
            norm2 += v[i] * v[i];
          }
        if (norm2 < 1e-12)
          return directions;
        for (unsigned int j = 0; j < n; ++j)
          for (const double s : {1., -1.})
            {
              Direction d;
              for (unsigned int i = 0; i < n; ++i)
                d.emplace_back(free[i],
                               s * ((i == j ? 1. : 0.) -
                                    2 * v[i] * v[j] / norm2));
              directions.push_back(d);
            }
        return directions;
      }
    } // namespace


    PatternSearch
    pattern_search(OutputObjective  &objective,
                   VectorType       &x,
                   double           &value,
                   const VectorType &lower,
                   const VectorType &upper,
                   const double      initial_step,
                   const double      final_step,
                   const double      noise)
    {
      const std::vector<unsigned int> free  = free_coordinates(lower, upper);
      const std::vector<Direction>    fixed = poll_directions(free);
      // improvement per number of halvings of the step
      std::map<unsigned int, double> improvement;
      unsigned int                   halvings = 0, idle = 0;
      double                         step = initial_step;
      PatternSearch                  result;
      unsigned int                   poll = 0;
      bool edge = false; // the last poll met points without a solution
      for (; poll < 10000; ++poll)
        {
          // Converged: three halvings in a row below the final step improved
          // nothing, or the search presses against the edge of the part of
          // the box with a solution, resolved to the final step (closer,
          // e.g. to the limit of equilibrium, the answer is degenerate).
          if (step < final_step && (idle >= 3 || edge))
            {
              result.converged = true;
              result.at_edge   = idle < 3;
              break;
            }
          if (step < final_step / 1024)
            break;
          std::vector<Direction> directions = fixed;
          for (Direction &d : turned_directions(free, poll + 1))
            directions.push_back(std::move(d));
          VectorType              best_x     = x;
          double                  best_value = value;
          std::vector<VectorType> polls;
          for (const auto &direction : directions)
            {
              VectorType y = x;
              for (const auto &[i, component] : direction)
                y[i] = std::min(std::max(x[i] + component * step *
                                                  (upper[i] - lower[i]),
                                         lower[i]),
                                upper[i]);
              if (y != x)
                polls.push_back(y);
            }
          objective.prefetch(polls);
          result.n_polls += polls.size();
          edge = false;
          for (const VectorType &y : polls)
            {
              const double f = objective.at(y);
              edge           = edge || !std::isfinite(f);
              if (f < best_value)
                {
                  best_value = f;
                  best_x     = y;
                }
            }
          if (best_value < value - noise)
            {
              // The speculative search of MADS (Audet and Dennis, SIAM J.
              // Optim. 17, 2006): on along the successful direction, twice
              // as far each time, while that improves (a ridge of kinks is
              // followed in a few steps once a direction along it is found).
              VectorType move = best_x;
              move -= x;
              for (unsigned int k = 0; k < 30; ++k)
                {
                  VectorType y = best_x;
                  y.add(std::pow(2., k), move);
                  for (unsigned int i = 0; i < y.size(); ++i)
                    y[i] = std::min(std::max(y[i], lower[i]), upper[i]);
                  if (y == best_x)
                    break;
                  ++result.n_polls;
                  const double f = objective.at(y);
                  if (!(f < best_value - noise))
                    break;
                  best_x     = y;
                  best_value = f;
                }
              improvement[halvings] += value - best_value;
              x     = best_x;
              value = best_value;
              idle  = 0;
            }
          else
            {
              step /= 2;
              ++halvings;
              ++idle;
            }
        }
      result.final_step = 2 * step;
      for (const auto &[h, change] : improvement)
        if (h + 3 > halvings)
          result.last_change += change;
      return result;
    }


    void
    shape_of_optimum(OutputObjective     &objective,
                     const Normalisation &normalisation,
                     const VectorType    &x,
                     const double         value,
                     const VectorType    &gradient,
                     const VectorType    &lower,
                     const VectorType    &upper,
                     const double         interior_tolerance,
                     const double         range,
                     const double         noise,
                     BoundQuality        &quality)
    {
      quality.interior.clear();
      quality.kinks.clear();
      quality.edge.clear();
      const double scale      = range > 0 ? range : 1.;
      double       projected2 = 0;
      bool         at_vertex  = true;
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          const double width = upper[i] - lower[i];
          if (width <= 0)
            continue;
          const double tol      = interior_tolerance * width;
          const bool   at_lower = x[i] <= lower[i] + tol;
          const bool   at_upper = x[i] >= upper[i] - tol;
          double       g        = gradient[i];
          if ((at_lower && g > 0) || (at_upper && g < 0))
            g = 0; // the box stops the descent
          if (!at_lower && !at_upper)
            {
              at_vertex = false;
              quality.interior.push_back(normalisation.free[i]);
              // One-sided slopes over a thousandth of the interval.
              const double h =
                std::min({1e-3 * width, x[i] - lower[i], upper[i] - x[i]});
              VectorType y      = x;
              y[i]              = x[i] + h;
              const double up   = objective.at(y);
              y[i]              = x[i] - h;
              const double down = objective.at(y);
              if (!std::isfinite(up) || !std::isfinite(down))
                {
                  // A neighbour without a solution: the bound lies at the
                  // edge of the part of the box with one, which stops the
                  // descent towards it, as the box's ends do.
                  quality.edge.push_back(normalisation.free[i]);
                  g = std::isfinite(up)     ? std::min(0., (up - value) / h)
                      : std::isfinite(down) ? std::max(0., (value - down) / h)
                                            : 0.;
                  projected2 += g * width * g * width;
                  continue;
                }
              const double right = (up - value) / h;
              const double left  = (value - down) / h;
              if ((right - left) * width > 0.01 * scale &&
                  up + down - 2 * value > 10 * noise)
                {
                  quality.kinks.push_back(normalisation.free[i]);
                  // A kink that is a minimum along i is first-order optimal
                  // there; otherwise the better one-sided slope remains.
                  g = (right >= -noise / h && left <= noise / h)
                        ? 0.
                        : (right < 0 ? right : left);
                }
            }
          projected2 += g * width * g * width;
        }
      quality.where              = at_vertex ? "vertex"
                                   : quality.interior.size() == normalisation.n_free()
                                     ? "interior"
                                     : "boundary";
      quality.projected_gradient = std::sqrt(projected2) / scale;
    }
  } // namespace LocalOptimisation
} // namespace FuzzyContact
