// The global stage and the refinement of the optimisation method
// (global_stage.h).

#include <fuzzycontact/fuzzy/global_stage.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    std::vector<VectorType>
    latin_hypercube(const unsigned int n_points,
                    const unsigned int dimension,
                    const unsigned int seed)
    {
      // std::mt19937's sequence is fixed by the standard; the shuffle and
      // the conversion to [0, 1) are done here so that they are too.
      std::mt19937 random(seed);
      const auto   uniform = [&]() {
        return (random() + 0.5) / 4294967296.;
      };
      std::vector<VectorType>   design(n_points, VectorType(dimension));
      std::vector<unsigned int> strata(n_points);
      for (unsigned int d = 0; d < dimension; ++d)
        {
          for (unsigned int i = 0; i < n_points; ++i)
            strata[i] = i;
          for (unsigned int i = n_points; i > 1; --i)
            std::swap(strata[i - 1], strata[random() % i]);
          for (unsigned int i = 0; i < n_points; ++i)
            design[i][d] = (strata[i] + uniform()) / n_points;
        }
      return design;
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


    std::vector<Candidate>
    global_stage(OutputObjective               &objective,
                 const std::vector<VectorType> &unit_design,
                 const std::vector<VectorType> &seeds,
                 const VectorType              &lower,
                 const VectorType              &upper)
    {
      const bool                               point = is_point(lower, upper);
      std::map<std::vector<double>, Candidate> unique;
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
      std::vector<Candidate> candidates;
      for (auto &entry : unique)
        candidates.push_back(std::move(entry.second));
      // Best first; ties keep the order of the coordinates (deterministic).
      std::stable_sort(candidates.begin(),
                       candidates.end(),
                       [](const Candidate &a, const Candidate &b) {
                         return a.value < b.value;
                       });
      return candidates;
    }


    std::vector<VectorType>
    local_starts(const std::vector<Candidate> &candidates,
                 const VectorType             &lower,
                 const VectorType             &upper,
                 const unsigned int            max_starts)
    {
      std::vector<VectorType> starts;
      if (candidates.empty())
        return starts;
      starts.push_back(candidates[0].x);
      if (candidates[0].vertex)
        return starts;
      const auto apart = [&](const VectorType &a, const VectorType &b) {
        for (unsigned int i = 0; i < a.size(); ++i)
          if (std::abs(a[i] - b[i]) > 0.25 * (upper[i] - lower[i]))
            return true;
        return false;
      };
      for (const Candidate &c : candidates)
        {
          if (starts.size() >= max_starts)
            break;
          bool far = true;
          for (const VectorType &s : starts)
            far = far && apart(c.x, s);
          if (far)
            starts.push_back(c.x);
        }
      return starts;
    }


    namespace
    {
      // The poll directions: +-e_i and, for up to four coordinates that can
      // move, +-e_i +- e_j.
      std::vector<std::vector<std::pair<unsigned int, double>>>
      poll_directions(const VectorType &lower, const VectorType &upper)
      {
        std::vector<unsigned int> free;
        for (unsigned int i = 0; i < lower.size(); ++i)
          if (upper[i] > lower[i])
            free.push_back(i);
        std::vector<std::vector<std::pair<unsigned int, double>>> directions;
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
      const auto directions = poll_directions(lower, upper);
      // improvement per number of halvings of the step
      std::map<unsigned int, double> improvement;
      unsigned int                   halvings = 0;
      double                         step     = initial_step;
      for (unsigned int poll = 0; step >= final_step && poll < 10000; ++poll)
        {
          VectorType              best_x     = x;
          double                  best_value = value;
          std::vector<VectorType> polls;
          for (const auto &direction : directions)
            {
              VectorType y = x;
              for (const auto &[i, sign] : direction)
                y[i] =
                  std::min(std::max(x[i] + sign * step * (upper[i] - lower[i]),
                                    lower[i]),
                           upper[i]);
              if (y != x)
                polls.push_back(y);
            }
          objective.prefetch(polls);
          for (const VectorType &y : polls)
            {
              const double f = objective.at(y);
              if (f < best_value)
                {
                  best_value = f;
                  best_x     = y;
                }
            }
          if (best_value < value - noise)
            {
              improvement[halvings] += value - best_value;
              x     = best_x;
              value = best_value;
            }
          else
            {
              step /= 2;
              ++halvings;
            }
        }
      PatternSearch result;
      result.final_step = 2 * step;
      for (const auto &[h, change] : improvement)
        if (h + 3 >= halvings)
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
              VectorType y       = x;
              y[i]               = x[i] + h;
              const double up    = objective.at(y);
              y[i]               = x[i] - h;
              const double down  = objective.at(y);
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
