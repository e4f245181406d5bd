// Tests of the fuzzy machinery: fuzzy numbers and alpha-cuts, fuzzy
// parameters bound to scene quantities, and the three interval methods,
// against interval bounds known in closed form.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/bound_proof.h>
#include <fuzzycontact/fuzzy/extension_principle.h>
#include <fuzzycontact/fuzzy/feasible_region.h>
#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/global_stage.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>
#include <fuzzycontact/fuzzy/proof_feedback.h>
#include <fuzzycontact/fuzzy/spot_checks.h>
#include <fuzzycontact/fuzzy/vertex_method.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_quantity.h>

#include <gtest/gtest.h>

#include "test_utilities.h"
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

using namespace FuzzyContact;
using namespace FuzzyContact::Testing;


// ----------------------------------------------------------------------------
// Fuzzy numbers
// ----------------------------------------------------------------------------

TEST(FuzzyNumber, AlphaCutsOfATriangle)
{
  const FuzzyNumber f = FuzzyNumber::triangular(10e3, 50e3, 100e3);
  EXPECT_EQ(f.alpha_cut(0).lower, 10e3);
  EXPECT_EQ(f.alpha_cut(0).upper, 100e3);
  EXPECT_EQ(f.alpha_cut(1).lower, 50e3);
  EXPECT_EQ(f.alpha_cut(1).upper, 50e3);
  EXPECT_DOUBLE_EQ(f.alpha_cut(0.25).lower, 20e3);
  EXPECT_DOUBLE_EQ(f.alpha_cut(0.25).upper, 87.5e3);
  EXPECT_DOUBLE_EQ(f.membership(30e3), 0.5);
  EXPECT_DOUBLE_EQ(f.membership(75e3), 0.5);
  EXPECT_EQ(f.membership(5e3), 0.);
  EXPECT_EQ(f.membership(50e3), 1.);
  // membership and alpha-cut are inverse to each other
  for (const double a : {0.1, 0.3, 0.7, 0.9})
    {
      EXPECT_NEAR(f.membership(f.alpha_cut(a).lower), a, 1e-12);
      EXPECT_NEAR(f.membership(f.alpha_cut(a).upper), a, 1e-12);
    }
}

TEST(FuzzyNumber, TrapezoidAndCrisp)
{
  const FuzzyNumber t = FuzzyNumber::trapezoidal(0, 1, 3, 4);
  EXPECT_EQ(t.alpha_cut(1).lower, 1.);
  EXPECT_EQ(t.alpha_cut(1).upper, 3.);
  EXPECT_DOUBLE_EQ(t.alpha_cut(0.5).lower, 0.5);
  EXPECT_DOUBLE_EQ(t.alpha_cut(0.5).upper, 3.5);
  EXPECT_EQ(t.membership(2), 1.);
  const FuzzyNumber c = FuzzyNumber::crisp(0.3);
  EXPECT_EQ(c.alpha_cut(0).lower, 0.3);
  EXPECT_EQ(c.alpha_cut(0).upper, 0.3);
  EXPECT_EQ(FuzzyNumber::triangular(1, 2, 4).scaled(2).alpha_cut(0).upper, 8.);
}

TEST(FuzzyNumber, BadInputIsRefusedWithAMessage)
{
  EXPECT_NE(error_of([] {
              FuzzyNumber::triangular(3, 2, 4, "F");
            }).find("F: the values must not decrease"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              FuzzyNumber::triangular(2, 2, 2, "F");
            }).find("F: the support [2.000000, 2.000000] is empty"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              FuzzyNumber::triangular(1, NAN, 2, "F");
            }).find("F: every value must be a finite number"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              FuzzyNumber::from("triangular", {1, 2}, "F");
            }).find("F: a triangular fuzzy number needs 3 values, got 2"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              FuzzyNumber::from("gaussian", {1}, "F");
            }).find("unknown shape <gaussian>"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              alpha_levels(1);
            }).find("number of alpha levels must be at least 2"),
            std::string::npos);
  const auto levels = alpha_levels(11);
  ASSERT_EQ(levels.size(), 11u);
  EXPECT_EQ(levels.front(), 0.);
  EXPECT_EQ(levels.back(), 1.);
  EXPECT_DOUBLE_EQ(levels[3], 0.3);
}


// ----------------------------------------------------------------------------
// Fuzzy parameters and scene quantities
// ----------------------------------------------------------------------------

TEST(SceneQuantity, NamesValuesAndErrors)
{
  Scene      scene = Scene::read(source_dir + "/prm/overlap.prm");
  const auto E1    = SceneQuantity::parse("P1.E", scene);
  EXPECT_EQ(E1.value(scene), 210e9);
  EXPECT_EQ(SceneQuantity::parse("P1.body.rho", scene).value(scene), 7900.);
  EXPECT_EQ(SceneQuantity::parse("P1.tip.force", scene).value(scene), 50000.);
  EXPECT_EQ(SceneQuantity::parse("interface.mu", scene).value(scene), 0.3);
  // 'auto' gap: P1's bottom at y = 1e-8, P2's top at y = 0.
  EXPECT_NEAR(SceneQuantity::parse("interface.gap", scene).value(scene),
              1e-8,
              1e-20);
  SceneState state(scene);
  E1.apply(state, scene, 200e9);
  EXPECT_EQ(state.zone_moduli[0][0], 200e9);
  EXPECT_EQ(state.zone_moduli[1][0], 210e9);

  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("P3.E", scene);
            }).find("Scene quantity <P3.E>: the scene has no component <P3>"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("P1.root.E", scene);
            }).find("component P1 has no zone called <root> (its zones: body)"),
            std::string::npos);
  EXPECT_NE(
    error_of([&] {
      SceneQuantity::parse("P2.tip.force", scene);
    })
      .find(
        "component P2 has no load <tip> (its loads and such supports: none)"),
    std::string::npos);
  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("P1.nu", scene);
            }).find("<nu> is not a quantity"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              E1.apply(state, scene, -1);
            }).find("P1.E must lie between 1000 and 1e+13"),
            std::string::npos);
}

TEST(FuzzyParameterSet, ReadsRelativeAndAbsoluteValues)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const std::string       text  = R"(
set fuzzy parameters = P1.E, P1.tip.force
subsection Fuzzy parameter P1.E
  set values   = 0.95, 1, 1.05
  set relative = true
end
subsection Fuzzy parameter P1.tip.force
  set shape  = trapezoidal
  set values = 10e3, 40e3, 60e3, 100e3
end
)";
  const FuzzyParameterSet set   = fuzzy_parameters(scene, text);
  ASSERT_EQ(set.parameters().size(), 2u);
  EXPECT_DOUBLE_EQ(set.numbers()[0].alpha_cut(0).lower, 0.95 * 210e9);
  EXPECT_DOUBLE_EQ(set.numbers()[0].alpha_cut(0).upper, 1.05 * 210e9);
  EXPECT_EQ(set.numbers()[1].alpha_cut(1).upper, 60e3);
  const SceneState changed = set.state(scene, {200e9, 20e3});
  EXPECT_EQ(changed.zone_moduli[0][0], 200e9);
  EXPECT_EQ(changed.load_forces[0][0], 20e3);
  EXPECT_EQ(changed.zone_moduli[1][0], 210e9);
}

TEST(FuzzyParameterSet, BadInputIsRefusedWithAMessage)
{
  const Scene scene = Scene::read(source_dir + "/prm/overlap.prm");
  const auto  parse = [&](const std::string &text) {
    return error_of([&] {
      fuzzy_parameters(scene, text);
    });
  };
  EXPECT_NE(parse("set fuzzy parameters = P1.G\nsubsection Fuzzy parameter "
                  "P1.G\nset values = 1,2,3\nend\n")
              .find("<G> is not a quantity"),
            std::string::npos);
  EXPECT_NE(parse("set fuzzy parameters = P1.E\nsubsection Fuzzy parameter "
                  "P1.E\nset values = 3,2,1\nend\n")
              .find("Fuzzy parameter P1.E: the values must not decrease"),
            std::string::npos);
  EXPECT_NE(parse("set fuzzy parameters = P1.E\nsubsection Fuzzy parameter "
                  "P1.E\nset values = 1, 1, 1\nend\n")
              .find("Fuzzy parameter P1.E: the support"),
            std::string::npos);
  EXPECT_NE(parse("set fuzzy parameters = P1.E\n").find("values"),
            std::string::npos); // mandatory entry missing
  EXPECT_NE(parse("set fuzzy parameters = P1.E\nsubsection Fuzzy parameter "
                  "P1.E\nset values = -1e9, 1e9, 2e9\nend\n")
              .find("P1.E must lie between 1000 and 1e+13"),
            std::string::npos);
  EXPECT_NE(parse("set fuzzy parameters = interface.mu\nsubsection Fuzzy "
                  "parameter interface.mu\nset values = -0.1, 0.3, 0.5\nend\n")
              .find("interface.mu must lie between 0 and 10"),
            std::string::npos);
  EXPECT_NE(parse("set fuzzy parameters = P1.E\nsubsection Fuzzy parameter "
                  "P1.E\nset values = 1, nan, 3\nend\n")
              .find("is not a finite number"),
            std::string::npos);
}


// ----------------------------------------------------------------------------
// Interval methods against closed-form bounds
// ----------------------------------------------------------------------------

namespace
{
  // The interval methods run on one process here.
  const MPI_Comm self = MPI_COMM_SELF;

  // The closed-form responses below are exact to round-off: a response
  // tolerance near round-off, not the default (1e-7, for the reduced
  // contact model), so that the checks for non-monotone responses see
  // every difference above round-off.
  OptimisationSettings
  closed_form_settings()
  {
    OptimisationSettings settings;
    settings.response_tolerance = 1e-12;
    return settings;
  }

  const std::vector<FuzzyNumber> three_parameters = {
    FuzzyNumber::triangular(0.95, 1.0, 1.05),
    FuzzyNumber::triangular(1.9, 2.0, 2.1),
    FuzzyNumber::triangular(10, 50, 100)};

  // Monotone in every parameter: the bounds are those of interval
  // arithmetic, attained at vertices.
  std::vector<double>
  monotone(const std::vector<double> &p)
  {
    return {p[2] / (p[0] + p[1]), p[0] * p[1] - 0.01 * p[2]};
  }

  std::vector<Interval>
  monotone_exact(const unsigned int output, const std::vector<double> &alpha)
  {
    std::vector<Interval> bounds;
    for (const double a : alpha)
      {
        const auto box = alpha_box(three_parameters, a);
        if (output == 0)
          bounds.push_back({box[2].lower / (box[0].upper + box[1].upper),
                            box[2].upper / (box[0].lower + box[1].lower)});
        else
          bounds.push_back({box[0].lower * box[1].lower - 0.01 * box[2].upper,
                            box[0].upper * box[1].upper - 0.01 * box[2].lower});
      }
    return bounds;
  }
} // namespace

TEST(IntervalMethods, AllThreeAreExactForAMonotoneResponse)
{
  const auto                     alpha = alpha_levels(11);
  const std::vector<std::string> names = {"S1", "S2"};
  const auto                     v =
    VertexMethod().bounds(three_parameters, alpha, monotone, names, self);
  const auto e = ExtensionPrinciple(4).bounds(three_parameters,
                                              alpha,
                                              monotone,
                                              names,
                                              self);
  const auto o = OptimisationMethod(closed_form_settings())
                   .bounds(three_parameters, alpha, monotone, names, self);
  for (unsigned int k = 0; k < 2; ++k)
    {
      const auto exact = monotone_exact(k, alpha);
      EXPECT_LT(max_relative_difference(v.bounds[k], exact), 1e-15);
      EXPECT_LT(max_relative_difference(e.bounds[k], exact), 1e-15);
      EXPECT_LT(max_relative_difference(o.bounds[k], exact), 1e-12);
    }
  EXPECT_TRUE(o.notes.empty()) << o.notes.front();
  // 8 vertices per level, the core is one point: 10 * 8 + 1.
  EXPECT_EQ(v.n_evaluations, 81u);
  // 4 x 4 x 4 points per box of the 10 levels below the core, plus the core.
  EXPECT_EQ(e.n_evaluations, 10u * 64u + 1u);
  EXPECT_EQ(extension_principle_size(three_parameters, alpha, 2), 81u);
}

// bounds_on_ranks() measures the time spent inside the response, apart
// from the method's own work: a response that busy-waits 2 ms per call
// accounts for at least 2 ms per evaluation, and the method's wall time
// holds all of it. (Lower bounds only: the machine may be slow, never
// fast.)
TEST(IntervalMethods, TheTimeInsideTheResponseIsMeasured)
{
  const std::vector<FuzzyNumber> parameters = {FuzzyNumber::triangular(1, 2, 3),
                                               FuzzyNumber::triangular(0,
                                                                       1,
                                                                       2)};
  unsigned int                   calls      = 0;
  const Response                 response = [&](const std::vector<double> &p) {
    ++calls;
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start <
           std::chrono::milliseconds(2))
      ;
    return std::vector<double>{p[0] + p[1]};
  };
  const std::vector<double> alpha = alpha_levels(3);
  const FuzzyOutputBounds   b     = bounds_on_ranks(VertexMethod(),
                                              parameters,
                                              alpha,
                                              response,
                                              {"S"},
                                              self,
                                              self);
  ASSERT_EQ(b.n_evaluations, calls);
  EXPECT_GE(b.evaluation_time, 2e-3 * calls);
  EXPECT_LE(b.evaluation_time, b.wall_time);
  // The methods themselves leave it to bounds_on_ranks().
  EXPECT_EQ(VertexMethod()
              .bounds(parameters, alpha, response, {"S"}, self)
              .evaluation_time,
            0.);
}

TEST(IntervalMethods, NonMonotoneResponseIsDetectedAndHandled)
{
  // S = (p0 - 1.02)^2 + 0.1 p1 has its minimum inside the box in p0 for
  // alpha <= 0.6 (where 1.02 lies in p0's alpha-cut), so the vertex method
  // overestimates the lower bound there.
  const std::vector<FuzzyNumber> parameters =
    {FuzzyNumber::triangular(0.9, 1.0, 1.1), FuzzyNumber::triangular(1, 2, 3)};
  const Response response = [](const std::vector<double> &p) {
    return std::vector<double>{(p[0] - 1.02) * (p[0] - 1.02) + 0.1 * p[1]};
  };
  const auto            alpha = alpha_levels(11);
  std::vector<Interval> exact;
  for (const double a : alpha)
    {
      const auto   box = alpha_box(parameters, a);
      const double lo0 = box[0].contains(1.02)
                           ? 0.
                           : std::min(std::pow(box[0].lower - 1.02, 2),
                                      std::pow(box[0].upper - 1.02, 2));
      const double hi0 = std::max(std::pow(box[0].lower - 1.02, 2),
                                  std::pow(box[0].upper - 1.02, 2));
      exact.push_back({lo0 + 0.1 * box[1].lower, hi0 + 0.1 * box[1].upper});
    }

  const auto v =
    VertexMethod().bounds(parameters, alpha, response, {"S"}, self);
  EXPECT_GT(max_relative_difference(v.bounds[0], exact), 1e-3);

  // The Extension Principle samples the box, so its interval lies inside
  // the exact one and closes in on it as the grid is refined (the minimum
  // of (p0 - 1.02)^2 on a grid of spacing h is at most (h/2)^2).
  double previous = 1;
  for (const unsigned int r : {5u, 21u, 81u})
    {
      const auto e =
        ExtensionPrinciple(r).bounds(parameters, alpha, response, {"S"}, self);
      for (unsigned int l = 0; l < alpha.size(); ++l)
        {
          EXPECT_GE(e.bounds[0][l].lower, exact[l].lower - 1e-15);
          EXPECT_LE(e.bounds[0][l].upper, exact[l].upper + 1e-15);
          const double h = alpha_box(parameters, alpha[l])[0].width() / (r - 1);
          EXPECT_LE(e.bounds[0][l].lower - exact[l].lower, h * h / 4 + 1e-15);
        }
      const double difference = max_relative_difference(e.bounds[0], exact);
      EXPECT_LE(difference, previous + 1e-15);
      previous = difference;
    }
  EXPECT_LT(previous, 1e-4);

  const auto o = OptimisationMethod(closed_form_settings())
                   .bounds(parameters, alpha, response, {"S"}, self);
  EXPECT_LT(max_relative_difference(o.bounds[0], exact), 1e-8);
  ASSERT_FALSE(o.notes.empty());
  EXPECT_NE(o.notes.front().find("non-monotone response"), std::string::npos)
    << o.notes.front();
  EXPECT_NE(o.notes.front().find("optimum inside the interval of parameter 1"),
            std::string::npos)
    << o.notes.front();
}

TEST(IntervalMethods, LocalOptimumTrapIsCaughtByTheVertexCheck)
{
  // S = cos(3 pi (p - 1) / 0.1) on p in [0.9, 1.1]: the global maximum 1
  // is at the core p = 1, the minimum -1 at p = 1 +- 1/30 and at both ends.
  // A local search for the lower bound started at p = 1 (the optimum of the
  // level above) would not move: the gradient vanishes there. The global
  // stage compares it with the vertices (S = -1) and starts from there.
  // The upper bound is an interior optimum: reported, and answered by the
  // global stage, or without one by the multi-start unless it is off.
  const std::vector<FuzzyNumber> parameters = {
    FuzzyNumber::triangular(0.9, 1.0, 1.1)};
  const Response response = [](const std::vector<double> &p) {
    return std::vector<double>{std::cos(3 * M_PI * (p[0] - 1) / 0.1)};
  };
  const std::vector<double> alpha = {0, 1};
  OptimisationSettings      with = closed_form_settings(), without = with;
  without.fallback           = false;
  without.global_points_auto = false;
  without.global_points      = 0;
  const auto o =
    OptimisationMethod(with).bounds(parameters, alpha, response, {"S"}, self);
  EXPECT_NEAR(o.bounds[0][0].lower, -1., 1e-12);
  EXPECT_NEAR(o.bounds[0][0].upper, 1., 1e-12);
  ASSERT_EQ(o.notes.size(), 1u);
  EXPECT_NE(o.notes.front().find("(upper bound), alpha = 0: non-monotone "
                                 "response (optimum inside the interval"),
            std::string::npos)
    << o.notes.front();
  EXPECT_NE(o.notes.front().find("found no better point"), std::string::npos)
    << o.notes.front();
  const auto stuck = OptimisationMethod(without).bounds(parameters,
                                                        alpha,
                                                        response,
                                                        {"S"},
                                                        self);
  EXPECT_NEAR(stuck.bounds[0][0].lower, -1., 1e-12);
  ASSERT_FALSE(stuck.notes.empty());
  EXPECT_NE(stuck.notes.front().find("no fallback"), std::string::npos);
}

namespace
{
  // A kinked response in the manner of a friction force that reverses:
  // S = min(2 p0, 3 (1 - p0)) (1 + 0.1 p1) on p0 in [0, 1]: it rises with
  // p0 up to the kink at p0 = 0.6 and falls beyond, so its maximum over a
  // box lies at the kink (if the box holds p0 = 0.6) and at p1's upper end.
  const std::vector<FuzzyNumber> kinked_parameters = {
    FuzzyNumber::triangular(0.15, 0.45, 0.95),
    FuzzyNumber::triangular(0, 1, 2)};

  std::vector<double>
  kinked(const std::vector<double> &p)
  {
    return {std::min(2 * p[0], 3 * (1 - p[0])) * (1 + 0.1 * p[1])};
  }

  Interval
  kinked_exact(const double alpha)
  {
    const auto box = alpha_box(kinked_parameters, alpha);
    const auto f   = [](const double p0) {
      return std::min(2 * p0, 3 * (1 - p0));
    };
    const double top =
      box[0].contains(0.6) ? 1.2 : std::max(f(box[0].lower), f(box[0].upper));
    return {std::min(f(box[0].lower), f(box[0].upper)) *
              (1 + 0.1 * box[1].lower),
            top * (1 + 0.1 * box[1].upper)};
  }
} // namespace

// The global stage and the pattern search find the maximum at the kink to
// far better than 1e-3 of the range at every level; the kink and the
// interior optimum are reported per level, the lower bound lies at a vertex,
// the alpha-cuts are nested, and the 4-point Extension Principle misses the
// kink (a sampled reference can only under-estimate an interval).
TEST(IntervalMethods, KinkedMaximumIsFoundAndReported)
{
  const auto alpha = alpha_levels(11);
  const auto o     = OptimisationMethod(closed_form_settings())
                   .bounds(kinked_parameters, alpha, kinked, {"S"}, self);
  const auto e =
    ExtensionPrinciple(4).bounds(kinked_parameters, alpha, kinked, {"S"}, self);
  const double range           = kinked_exact(0).upper - kinked_exact(0).lower;
  double       reference_short = 0;
  for (unsigned int l = 0; l < alpha.size(); ++l)
    {
      const Interval exact = kinked_exact(alpha[l]);
      EXPECT_NEAR(o.bounds[0][l].lower, exact.lower, 1e-12 * range);
      EXPECT_NEAR(o.bounds[0][l].upper, exact.upper, 1e-6 * range)
        << "alpha = " << alpha[l];
      EXPECT_EQ(o.lower_quality[0][l].where, "vertex");
      const BoundQuality &q   = o.upper_quality[0][l];
      const Interval      cut = alpha_box(kinked_parameters, alpha[l])[0];
      if (cut.lower < 0.6 - 1e-9 && cut.upper > 0.6 + 1e-9)
        {
          EXPECT_EQ(q.where, "boundary") << "alpha = " << alpha[l];
          EXPECT_EQ(q.kinks, std::vector<unsigned int>{0});
          EXPECT_TRUE(q.refined);
          // the pattern search stopped converged: three halvings below the
          // refinement step (1e-6) in a row improved nothing
          EXPECT_TRUE(q.search_converged);
          EXPECT_EQ(q.last_change, 0.);
          EXPECT_LT(q.final_step, 2e-6);
          EXPECT_TRUE(q.converged) << "alpha = " << alpha[l];
        }
      else
        EXPECT_EQ(q.where, "vertex") << "alpha = " << alpha[l];
      if (l > 0) // nested: each level's interval contains the next one's
        {
          EXPECT_LE(o.bounds[0][l - 1].lower, o.bounds[0][l].lower);
          EXPECT_GE(o.bounds[0][l - 1].upper, o.bounds[0][l].upper);
        }
      reference_short =
        std::max(reference_short, (exact.upper - e.bounds[0][l].upper) / range);
      // the method's upper bound, verified here by the closed form, lies
      // beyond the reference's: the reference missed it
      const auto c = compare_with_reference(o.bounds[0][l].upper,
                                            kinked(o.argmax[0][l])[0],
                                            e.bounds[0][l].upper,
                                            true,
                                            range);
      EXPECT_EQ(c.short_of_reference, 0.);
      if (exact.upper - e.bounds[0][l].upper > 1e-6 * range)
        {
          EXPECT_GT(c.reference_missed, 0.);
        }
    }
  EXPECT_GT(reference_short, 0.01);
}

namespace
{
  // A largest value whose place jumps, in the manner of a largest nodal
  // pressure: S = p1 + p2 + p3 + h(p0), h two narrow tents, 0.2 high at
  // p0 = 0.5 (the core) and 0.5 high at p0 = 0.225, half a width of 0.03
  // (the box's lower end of p0 steps 0.25, 0.2 between two levels: it
  // jumps over the second tent's peak).
  // From the core down the bound follows the first tent; once the box
  // holds the second, a higher peak lies on the line through the bound
  // along p0, where no design point of a few per parameter falls with
  // p1..p3 near their upper ends.
  const std::vector<FuzzyNumber> two_tents_parameters = {
    FuzzyNumber::triangular(0, 0.5, 1),
    FuzzyNumber::triangular(0, 0.5, 1),
    FuzzyNumber::triangular(0, 0.5, 1),
    FuzzyNumber::triangular(0, 0.5, 1)};

  double
  two_tents(const double p0)
  {
    return std::max({0.,
                     0.2 * (1 - std::abs(p0 - 0.5) / 0.03),
                     0.5 * (1 - std::abs(p0 - 0.225) / 0.03)});
  }

  std::vector<double>
  two_tents_response(const std::vector<double> &p)
  {
    return {p[1] + p[2] + p[3] + two_tents(p[0])};
  }

  // h is piecewise linear: its largest value over an interval lies at an
  // end or at a peak inside.
  double
  two_tents_upper(const double alpha)
  {
    const auto box = alpha_box(two_tents_parameters, alpha);
    double     top = std::max(two_tents(box[0].lower), two_tents(box[0].upper));
    for (const double peak : {0.225, 0.5})
      if (box[0].contains(peak))
        top = std::max(top, two_tents(peak));
    return box[1].upper + box[2].upper + box[3].upper + top;
  }
} // namespace

// A chain that met a kink in p0 scans lines through its bound along p0 at
// the levels below: the higher tent is found at every level whose box
// holds it, to 1e-6 of the range (the pattern search's refinement step),
// and the bound says so (scanned, gain). Without the scans (line scan
// points = 0) the search stays on the first tent, 0.3 short.
TEST(IntervalMethods, LinesThroughAKinkedBoundFindAPeakTheDesignMisses)
{
  const auto alpha = alpha_levels(11);
  const auto o =
    OptimisationMethod(closed_form_settings())
      .bounds(two_tents_parameters, alpha, two_tents_response, {"S"}, self);
  const double range = two_tents_upper(0) - 0.;
  bool         moved = false;
  for (unsigned int l = 0; l < alpha.size(); ++l)
    {
      EXPECT_NEAR(o.bounds[0][l].upper, two_tents_upper(alpha[l]), 1e-6 * range)
        << "alpha = " << alpha[l];
      const BoundQuality &q = o.upper_quality[0][l];
      if (q.scan_gain > 0)
        {
          moved = true;
          EXPECT_EQ(q.scanned, std::vector<unsigned int>{0});
        }
    }
  EXPECT_TRUE(moved);

  OptimisationSettings without = closed_form_settings();
  without.line_scan_points     = 0;
  const auto stuck = OptimisationMethod(without).bounds(two_tents_parameters,
                                                        alpha,
                                                        two_tents_response,
                                                        {"S"},
                                                        self);
  EXPECT_LT(stuck.bounds[0][0].upper, two_tents_upper(0) - 0.2);
  EXPECT_TRUE(stuck.upper_quality[0][0].scanned.empty());
}

// The design is a (t, m, d)-net of 2^m points: one in every stratum of
// every coordinate and, the first two Sobol coordinates being a (0, m,
// 2)-net, one in every elementary box 2^-a x 2^-(m - a) of them (random
// linear scrambling and a digital shift keep both); the same for the same
// seed, another for another.
TEST(GlobalStage, ScrambledSobolIsANet)
{
  using namespace LocalOptimisation;
  const unsigned int m = 6, n = 1u << m;
  const auto         design = scrambled_sobol(n, 3, 7);
  ASSERT_EQ(design.size(), n);
  for (unsigned int d = 0; d < 3; ++d)
    {
      std::set<unsigned int> strata;
      for (const auto &x : design)
        {
          EXPECT_GT(x[d], 0.);
          EXPECT_LT(x[d], 1.);
          strata.insert(static_cast<unsigned int>(x[d] * n));
        }
      EXPECT_EQ(strata.size(), n) << "coordinate " << d;
    }
  for (unsigned int a = 0; a <= m; ++a)
    {
      std::set<std::pair<unsigned int, unsigned int>> boxes;
      for (const auto &x : design)
        boxes.insert({static_cast<unsigned int>(x[0] * (1u << a)),
                      static_cast<unsigned int>(x[1] * (1u << (m - a)))});
      EXPECT_EQ(boxes.size(), n) << "boxes 2^-" << a << " x 2^-" << m - a;
    }
  EXPECT_EQ(scrambled_sobol(n, 3, 7)[5], design[5]);
  EXPECT_NE(scrambled_sobol(n, 3, 8)[5], design[5]);
  // The default size grows with the number of parameters, a power of two.
  EXPECT_EQ(default_design_points(1), 32u);
  EXPECT_EQ(default_design_points(2), 64u);
  EXPECT_EQ(default_design_points(3), 128u);
  EXPECT_EQ(default_design_points(5), 256u);
}

// A local optimisation stopped by its iteration limit with the optimum
// inside the box: the note says so, and does not say that an end of an
// interval was better (it was not).
TEST(IntervalMethods, IterationLimitNoteSaysOnlyWhatHappened)
{
  const std::vector<FuzzyNumber> parameters =
    {FuzzyNumber::triangular(0, 0.5, 1), FuzzyNumber::triangular(0, 0.5, 1)};
  const Response response = [](const std::vector<double> &p) {
    return std::vector<double>{std::pow(p[0] - 0.37, 2) +
                               3 * std::pow(p[1] - 0.41, 2) +
                               std::pow(p[0] - p[1], 2)};
  };
  OptimisationSettings settings = closed_form_settings();
  settings.max_iterations       = 1;
  const auto o =
    OptimisationMethod(settings).bounds(parameters, {0}, response, {"S"}, self);
  bool limit = false;
  for (const std::string &note : o.notes)
    {
      EXPECT_EQ(note.find("moved there"), std::string::npos) << note;
      limit = limit || note.find("ROL stopped at its iteration limit (1 "
                                 "iterations); no end of a parameter "
                                 "interval was better") != std::string::npos;
    }
  EXPECT_TRUE(limit);
  EXPECT_TRUE(o.lower_quality[0][0].iteration_limit);
  EXPECT_EQ(o.lower_quality[0][0].where, "interior");
  EXPECT_TRUE(o.lower_quality[0][0].kinks.empty());
  // the pattern search finishes what ROL left: the quadratic's minimum, at
  // p0 = 5.42 / 14, p1 = 2 p0 - 0.37 (where its gradient vanishes)
  const double p0 = 5.42 / 14, p1 = 2 * p0 - 0.37;
  EXPECT_NEAR(o.bounds[0][0].lower, response({p0, p1})[0], 1e-10);
}

// Each bound's argument is evaluated once more by the exact model: distinct
// points once, the difference at every bound; the comparison with a
// reference tells a reference's miss from a reduction error.
TEST(IntervalMethods, BoundProofsEvaluateEachArgumentOnce)
{
  unsigned int   calls = 0;
  const Response exact = [&](const std::vector<double> &p) {
    ++calls;
    return monotone(p);
  };
  const Response reduced = [](const std::vector<double> &p) {
    auto s = monotone(p);
    return std::vector<double>{s[0] * (1 + 1e-6), s[1] + 1e-9};
  };
  const auto alpha = alpha_levels(5);
  const auto o =
    OptimisationMethod(closed_form_settings())
      .bounds(three_parameters, alpha, reduced, {"S1", "S2"}, self);
  const BoundProofs             proofs = prove_bounds(o, exact, self);
  std::set<std::vector<double>> distinct;
  for (unsigned int k = 0; k < 2; ++k)
    for (unsigned int l = 0; l < alpha.size(); ++l)
      {
        distinct.insert(o.argmin[k][l]);
        distinct.insert(o.argmax[k][l]);
        const BoundProof &lo = proofs.lower[k][l];
        EXPECT_EQ(lo.reduced, o.bounds[k][l].lower);
        EXPECT_EQ(lo.exact, monotone(o.argmin[k][l])[k]);
        EXPECT_NEAR(lo.difference(),
                    k == 0 ? 1e-6 * lo.exact : 1e-9,
                    1e-15 * std::abs(lo.exact) + 1e-15);
        EXPECT_EQ(proofs.upper[k][l].exact, monotone(o.argmax[k][l])[k]);
      }
  EXPECT_EQ(proofs.n_evaluations, distinct.size());
  EXPECT_EQ(calls, distinct.size());
  EXPECT_LT(distinct.size(), 4u * alpha.size()); // bounds share arguments

  // lower bounds against a reference lower bound of 1 on a range of 10
  const auto short_of = compare_with_reference(1.5, 1.5, 1, false, 10);
  EXPECT_DOUBLE_EQ(short_of.short_of_reference, 0.05);
  const auto missed = compare_with_reference(0.5, 0.6, 1, false, 10);
  EXPECT_DOUBLE_EQ(missed.reference_missed, 0.04);
  EXPECT_EQ(missed.outside_not_verified, 0.);
  const auto reduction = compare_with_reference(0.5, 1.2, 1, false, 10);
  EXPECT_EQ(reduction.reference_missed, 0.);
  EXPECT_DOUBLE_EQ(reduction.outside_not_verified, 0.05);
}

TEST(IntervalMethods, CacheCountsDistinctEvaluations)
{
  unsigned int    calls = 0;
  EvaluationCache cache([&](const std::vector<double> &p) {
    ++calls;
    return std::vector<double>{p[0]};
  });
  cache({1.0});
  cache({2.0});
  cache({1.0});
  EXPECT_EQ(calls, 2u);
  EXPECT_EQ(cache.n_evaluations(), 2u);
}

// prefetch() evaluates the points not known yet, each once, and counts
// them as evaluations made here; the values are those of the response.
TEST(IntervalMethods, CachePrefetchEvaluatesNewPointsOnce)
{
  unsigned int    calls = 0;
  EvaluationCache cache([&](const std::vector<double> &p) {
    ++calls;
    return std::vector<double>{2 * p[0]};
  });
  cache({2.0});
  cache.prefetch({{1.0}, {2.0}, {1.0}, {3.0}});
  EXPECT_EQ(calls, 3u);
  EXPECT_EQ(cache.n_evaluations(), 3u);
  EXPECT_EQ(cache.n_evaluated_here(), 3u);
  EXPECT_EQ(cache({3.0})[0], 6.0);
  cache.prefetch({{3.0}});
  EXPECT_EQ(calls, 3u);
}

// The optimisation method evaluates every level's fixed points ahead
// (spread over the ranks): they must be exactly the points of the global
// stage apart from its seeds. After prefetching them, the global stage
// evaluates nothing new but its seeds that are not among them.
TEST(GlobalStage, FixedPointsAreThePointsOfTheStageButItsSeeds)
{
  using namespace LocalOptimisation;
  const std::vector<FuzzyNumber> parameters = {FuzzyNumber::triangular(1, 2, 4),
                                               FuzzyNumber::triangular(-1,
                                                                       0,
                                                                       3)};
  unsigned int                   calls      = 0;
  EvaluationCache                cache([&](const std::vector<double> &p) {
    ++calls;
    return std::vector<double>{p[0] * p[0] - 0.3 * p[1]};
  });
  const Normalisation            normalisation(parameters);
  const auto                     design = scrambled_sobol(8, 2, 3);
  for (const double alpha : {0., 0.5, 1.})
    {
      const auto [lo, hi] = normalisation.box(parameters, alpha);
      const std::vector<VectorType> fixed = fixed_points(design, lo, hi);
      // 4 vertices and the design, or the one point of the core
      EXPECT_EQ(fixed.size(), alpha < 1 ? 4u + 8u : 4u);
      std::vector<std::vector<double>> points;
      for (const VectorType &x : fixed)
        points.push_back(normalisation.parameters(x));
      cache.prefetch(points);
      OutputObjective objective(cache, normalisation, 0, 1., 1., 1e-4, lo, hi);
      VectorType      seed(2);
      seed[0] = 0.5 * (lo[0] + hi[0]) + 1e-3 * (hi[0] - lo[0]);
      seed[1] = lo[1];
      const unsigned int before = calls;
      global_stage(objective, design, {}, lo, hi);
      EXPECT_EQ(calls, before);
      global_stage(objective, design, {seed}, lo, hi);
      EXPECT_EQ(calls, before + (alpha < 1 ? 1u : 0u));
    }
}

// The three methods behind their interface, on a response monotone in each
// parameter over the boxes (so that all three are exact), with a
// trapezoidal parameter (a core of non-zero width):
//   S1 = p0^2 exp(-p1) + 3 p2: increasing in p0 > 0 and p2, decreasing in p1;
//   S2 = p1 / p0: increasing in p1 > 0, decreasing in p0 > 0;
// so the bounds over a box are S1 at (lower, upper, lower) and (upper,
// lower, upper), S2 at (upper, lower, *) and (lower, upper, *).
TEST(IntervalMethods, EachMethodThroughTheInterfaceIsExactWhenMonotone)
{
  const std::vector<FuzzyNumber> parameters = {
    FuzzyNumber::trapezoidal(1, 1.5, 2, 3),
    FuzzyNumber::triangular(0.1, 0.2, 0.4),
    FuzzyNumber::triangular(-1, 0, 2)};
  const Response response = [](const std::vector<double> &p) {
    return std::vector<double>{p[0] * p[0] * std::exp(-p[1]) + 3 * p[2],
                               p[1] / p[0]};
  };
  const auto                         alpha = alpha_levels(5);
  std::vector<std::vector<Interval>> exact(2);
  for (const double a : alpha)
    {
      const auto b = alpha_box(parameters, a);
      exact[0].push_back(
        {b[0].lower * b[0].lower * std::exp(-b[1].upper) + 3 * b[2].lower,
         b[0].upper * b[0].upper * std::exp(-b[1].lower) + 3 * b[2].upper});
      exact[1].push_back({b[1].lower / b[0].upper, b[1].upper / b[0].lower});
    }

  std::vector<std::unique_ptr<IntervalMethod>> methods;
  methods.push_back(std::make_unique<VertexMethod>());
  methods.push_back(std::make_unique<ExtensionPrinciple>(3));
  methods.push_back(
    std::make_unique<OptimisationMethod>(closed_form_settings()));
  // The sampling methods evaluate the exact corners; the optimisation ends
  // on them up to the round-off of the normalised coordinates.
  const std::vector<double> tolerance = {0, 0, 1e-13};
  std::set<std::string>     names;
  for (unsigned int m = 0; m < methods.size(); ++m)
    {
      const IntervalMethod   &method = *methods[m];
      const FuzzyOutputBounds b =
        method.bounds(parameters, alpha, response, {"S1", "S2"}, self);
      names.insert(method.name());
      EXPECT_EQ(b.alpha, alpha);
      EXPECT_GT(b.n_evaluations, 0u);
      EXPECT_TRUE(b.notes.empty()) << method.name() << ": " << b.notes[0];
      ASSERT_EQ(b.bounds.size(), 2u) << method.name();
      for (unsigned int k = 0; k < 2; ++k)
        {
          ASSERT_EQ(b.bounds[k].size(), alpha.size());
          EXPECT_LE(max_relative_difference(b.bounds[k], exact[k]),
                    tolerance[m])
            << method.name() << ", S" << k + 1;
          // Each bound is the response where it is said to be attained.
          for (unsigned int l = 0; l < alpha.size(); ++l)
            {
              const double lower = b.bounds[k][l].lower;
              const double upper = b.bounds[k][l].upper;
              EXPECT_NEAR(response(b.argmin[k][l])[k],
                          lower,
                          1e-14 * std::abs(lower));
              EXPECT_NEAR(response(b.argmax[k][l])[k],
                          upper,
                          1e-14 * std::abs(upper));
            }
        }
    }
  EXPECT_EQ(names.size(), 3u); // three different names
}

// Two wells of different depth: the design's basins are told apart
// (nearest-better roots, confirmed by the hill-valley test) and the local
// searches start in each, the deeper first; a response with one basin (a
// plane) gets one start, whatever the roots of its clustering.
TEST(GlobalStage, StartsComeFromDistinctBasins)
{
  using namespace LocalOptimisation;
  const std::vector<FuzzyNumber> parameters =
    {FuzzyNumber::triangular(0, 0.5, 1), FuzzyNumber::triangular(0, 0.5, 1)};
  const Normalisation normalisation(parameters);
  const auto [lo, hi] = normalisation.box(parameters, 0.);
  const auto design   = scrambled_sobol(128, 2, 1);
  const auto well     = [](const std::vector<double> &p,
                       const double               x,
                       const double               y,
                       const double               depth) {
    return depth *
           std::exp(-(std::pow(p[0] - x, 2) + std::pow(p[1] - y, 2)) / 0.02);
  };
  EvaluationCache two([&](const std::vector<double> &p) {
    return std::vector<double>{-well(p, 0.25, 0.3, 1.) -
                               well(p, 0.75, 0.7, 0.8)};
  });
  OutputObjective wells(two, normalisation, 0, 1., 1., 1e-4, lo, hi);
  const auto      stage = global_stage(wells, design, {}, lo, hi);
  const Starts starts = basin_starts(wells, stage.candidates, lo, hi, 3, 1e-12);
  ASSERT_EQ(starts.points.size(), 2u);
  EXPECT_GE(starts.n_roots, 2u);
  const auto near = [](const VectorType &x, const double a, const double b) {
    return std::hypot(x[0] - a, x[1] - b) < 0.15;
  };
  EXPECT_TRUE(near(starts.points[0].x, 0.25, 0.3)) << starts.points[0].x;
  EXPECT_TRUE(near(starts.points[1].x, 0.75, 0.7)) << starts.points[1].x;

  EvaluationCache plane([](const std::vector<double> &p) {
    return std::vector<double>{p[0] + 2 * p[1]};
  });
  OutputObjective flat(plane, normalisation, 0, 1., 1., 1e-4, lo, hi);
  const auto      one = global_stage(flat, design, {}, lo, hi);
  EXPECT_EQ(basin_starts(flat, one.candidates, lo, hi, 3, 1e-12).points.size(),
            1u);

  // An output the parameters cannot change (a total force held by statics)
  // varies by round-off only, in no order: its design shows one basin
  // (every root tested), not the many roots of a clustering of round-off.
  EvaluationCache roundoff([](const std::vector<double> &p) {
    return std::vector<double>{1. + 1e-15 * std::sin(1e3 * (p[0] + 7 * p[1]))};
  });
  OutputObjective constant(roundoff, normalisation, 0, 1., 1., 1e-4, lo, hi);
  const auto      none = global_stage(constant, design, {}, lo, hi);
  ASSERT_GT(nearest_better_roots(none.candidates, lo, hi).size(), 8u);
  const Starts level =
    basin_starts(constant, none.candidates, lo, hi, 3, 1e-12);
  EXPECT_EQ(level.points.size(), 1u);
  EXPECT_EQ(level.n_roots, 1u);
  EXPECT_TRUE(level.all_roots_tested);
}

namespace
{
  // A ridge of kinks across the coordinate directions and their
  // diagonals: S = p0 + p1 - 5 |p1 - 0.3 - 0.4 p0| on [0, 1]^2 falls along
  // each of them from any point of the ridge p1 = 0.3 + 0.4 p0, and rises
  // along the ridge to its maximum 1.7 at (1, 0.7). The shape of a
  // friction force at the kink where a contact starts to stick, which moves
  // with two parameters at once.
  std::vector<double>
  ridge(const std::vector<double> &p)
  {
    return {p[0] + p[1] - 5 * std::abs(p[1] - 0.3 - 0.4 * p[0])};
  }
} // namespace

// A compass search (coordinates and diagonals) started on the ridge would
// not move; the turned directions find the way along it, to the maximum
// within 1e-3 of the range (4.2), and the search stops converged. The
// optimisation method finds the same bound and calls it converged.
TEST(GlobalStage, PatternSearchFollowsARidgeOfKinks)
{
  using namespace LocalOptimisation;
  const std::vector<FuzzyNumber> parameters =
    {FuzzyNumber::triangular(0, 0.5, 1), FuzzyNumber::triangular(0, 0.5, 1)};
  const Normalisation normalisation(parameters);
  const auto [lo, hi] = normalisation.box(parameters, 0.);
  EvaluationCache cache(ridge);
  OutputObjective objective(cache, normalisation, 0, -1., 1., 1e-4, lo, hi);
  VectorType      x(2);
  x[0]             = 0.2;
  x[1]             = 0.38;
  double     value = objective.at(x);
  const auto search =
    pattern_search(objective, x, value, lo, hi, 1. / 16, 1e-6, 1e-12);
  const double range = 1.7 - (-2.5);
  EXPECT_NEAR(-value, 1.7, 1e-3 * range) << x;
  EXPECT_TRUE(search.converged);

  const auto o = OptimisationMethod(closed_form_settings())
                   .bounds(parameters, {0.}, ridge, {"S"}, self);
  EXPECT_NEAR(o.bounds[0][0].upper, 1.7, 1e-3 * range);
  EXPECT_NEAR(o.bounds[0][0].lower, -2.5, 1e-9);
  EXPECT_TRUE(o.upper_quality[0][0].converged) << o.upper_quality[0][0].where;
  EXPECT_TRUE(o.lower_quality[0][0].converged);
}

namespace
{
  // A response without a solution on part of the box, like a block held
  // by friction alone: p0 a friction coefficient, p1 a load; no solution
  // where p0 < 0.1 + 0.005 p1 (a convex set of loads per friction
  // coefficient, growing with it: the vertices of a box decide). Outputs
  // S0 = p0 p1 and S1 = p1.
  const std::vector<FuzzyNumber> sliding_parameters = {
    FuzzyNumber::triangular(0.1, 0.2, 0.3),
    FuzzyNumber::triangular(10, 15, 20)};

  bool
  holds(const std::vector<double> &p)
  {
    return p[0] >= 0.1 + 0.005 * p[1];
  }

  std::vector<double>
  sliding_response(const std::vector<double> &p)
  {
    if (!holds(p))
      return {};
    return {p[0] * p[1], p[1]};
  }
} // namespace

// Every method bounds the outputs over the part of each box with a
// solution and counts the points without one; the feasible region's
// membership (sliding possible below alpha = 0.8, where p0's lower end
// 0.1 + 0.1 alpha meets 0.1 + 0.005 p1's upper end 20 - 5 alpha) and where
// it starts (p0 = 0.18, p1 = 16) are the closed form's.
TEST(IntervalMethods, PointsWithoutASolutionAreLeftOut)
{
  const auto alpha = alpha_levels(6);
  // Over the part with a solution: S0 from p1's lower end at the larger of
  // p0's lower end and the edge, to both upper ends; S1 over p1's cut.
  const auto exact = [](const double a) {
    const auto b = alpha_box(sliding_parameters, a);
    return std::array<Interval, 2>{
      {Interval{b[1].lower * std::max(b[0].lower, 0.1 + 0.005 * b[1].lower),
                b[0].upper * b[1].upper},
       Interval{b[1].lower, b[1].upper}}};
  };
  const double range = 6. - 1.5;
  const auto   o =
    OptimisationMethod(closed_form_settings())
      .bounds(sliding_parameters, alpha, sliding_response, {"S0", "S1"}, self);
  const auto v = VertexMethod().bounds(sliding_parameters,
                                       alpha,
                                       sliding_response,
                                       {"S0", "S1"},
                                       self);
  const auto e = ExtensionPrinciple(11).bounds(sliding_parameters,
                                               alpha,
                                               sliding_response,
                                               {"S0", "S1"},
                                               self);
  for (unsigned int l = 0; l < alpha.size(); ++l)
    {
      const auto x = exact(alpha[l]);
      EXPECT_NEAR(o.bounds[0][l].lower, x[0].lower, 1e-6 * range)
        << "alpha = " << alpha[l];
      EXPECT_NEAR(o.bounds[0][l].upper, x[0].upper, 1e-12 * range);
      EXPECT_NEAR(o.bounds[1][l].lower, x[1].lower, 1e-12);
      EXPECT_NEAR(o.bounds[1][l].upper, x[1].upper, 1e-12);
      // every argument has a solution
      EXPECT_TRUE(holds(o.argmin[0][l]));
      EXPECT_TRUE(holds(o.argmax[0][l]));
      // the sampled methods lie inside, and count the points left out
      EXPECT_GE(e.bounds[0][l].lower, x[0].lower - 1e-12);
      EXPECT_GE(v.bounds[0][l].lower, x[0].lower - 1e-12);
      const bool sliding = alpha[l] < 0.8 - 1e-12;
      EXPECT_EQ(v.n_infeasible[l] > 0, sliding) << "alpha = " << alpha[l];
      EXPECT_EQ(e.n_infeasible[l] > 0, sliding) << "alpha = " << alpha[l];
      EXPECT_EQ(o.n_infeasible[l] > 0, sliding) << "alpha = " << alpha[l];
    }
  // The vertex method's samples in the support's box: the vertices of
  // every level, 5 x 4 + 1; without a solution (0.1 + 0.1 alpha, 10 + 5
  // alpha) for alpha < 2/3 and (0.1 + 0.1 alpha, 20 - 5 alpha) for alpha <
  // 0.8: 4 + 4 of them.
  EXPECT_EQ(v.n_points[0], 21u);
  EXPECT_EQ(v.n_infeasible[0], 8u);
  // the lower bound of S0 lies on the edge of the part with a solution
  EXPECT_EQ(o.lower_quality[0][0].edge, std::vector<unsigned int>{0});

  const FeasibleRegion region =
    feasible_region(sliding_parameters, alpha, holds, 64);
  EXPECT_TRUE(region.possible);
  EXPECT_TRUE(region.vertices_decide);
  EXPECT_NEAR(region.membership, 0.8, 1e-10);
  ASSERT_EQ(region.starts_at.size(), 2u);
  EXPECT_NEAR(region.starts_at[0], 0.18, 1e-10);
  EXPECT_NEAR(region.starts_at[1], 16., 1e-9);
  // at the support: (0.1, 10) has no solution; along p0 it starts at 0.15
  // (along p1 the neighbour (0.1, 20) has none either); the share of the
  // box with one is 1 - 0.075 / 0.2 = 0.625 (a Sobol estimate)
  const LevelFeasibility &support = region.levels[0];
  EXPECT_TRUE(support.possible);
  ASSERT_EQ(support.boundary.size(), 1u);
  EXPECT_EQ(support.boundary[0].parameter, 0u);
  EXPECT_NEAR(support.boundary[0].point[0], 0.15, 1e-9);
  EXPECT_NEAR(support.feasible_fraction(), 0.625, 0.03);
  EXPECT_FALSE(region.levels.back().possible);
}

// One default per setting, stated once: the parameter file's defaults are
// those of the struct.
TEST(IntervalMethods, OptimisationDefaultsOfTheParameterFileAreTheStructs)
{
  dealii::ParameterHandler prm;
  OptimisationSettings::declare_parameters(prm);
  prm.parse_input_from_string("");
  OptimisationSettings parsed; // every value different from the default
  parsed.algorithm              = "quasi-newton";
  parsed.gradient_tolerance     = 0.5;
  parsed.step_tolerance         = 0.5;
  parsed.max_iterations         = 7;
  parsed.finite_difference_step = 0.05;
  parsed.interior_tolerance     = 0.5;
  parsed.response_tolerance     = 1e-3;
  parsed.fallback               = false;
  parsed.global_points_auto     = false;
  parsed.global_points          = 5;
  parsed.global_time_limit      = 1;
  parsed.local_starts           = 9;
  parsed.refinement_step        = 0.01;
  parsed.line_scan_points       = 3;
  parsed.parse_parameters(prm);
  const OptimisationSettings defaults;
  EXPECT_EQ(parsed.algorithm, defaults.algorithm);
  EXPECT_EQ(parsed.gradient_tolerance, defaults.gradient_tolerance);
  EXPECT_EQ(parsed.step_tolerance, defaults.step_tolerance);
  EXPECT_EQ(parsed.max_iterations, defaults.max_iterations);
  EXPECT_EQ(parsed.finite_difference_step, defaults.finite_difference_step);
  EXPECT_EQ(parsed.interior_tolerance, defaults.interior_tolerance);
  EXPECT_EQ(parsed.response_tolerance, defaults.response_tolerance);
  EXPECT_EQ(parsed.fallback, defaults.fallback);
  EXPECT_EQ(parsed.global_points_auto, defaults.global_points_auto);
  EXPECT_EQ(parsed.global_time_limit, defaults.global_time_limit);
  EXPECT_EQ(parsed.local_starts, defaults.local_starts);
  EXPECT_EQ(parsed.refinement_step, defaults.refinement_step);
  EXPECT_EQ(parsed.line_scan_points, defaults.line_scan_points);
  EXPECT_TRUE(defaults.global_points_auto);
  // "global points" takes a number too, and refuses anything else
  prm.enter_subsection("Optimisation");
  prm.set("global points", "64");
  prm.leave_subsection();
  parsed.parse_parameters(prm);
  EXPECT_FALSE(parsed.global_points_auto);
  EXPECT_EQ(parsed.global_points, 64u);
  prm.enter_subsection("Optimisation");
  prm.set("global points", "many");
  prm.leave_subsection();
  EXPECT_NE(error_of([&]() {
              parsed.parse_parameters(prm);
            })
              .find("Optimisation: global points must be auto or an integer "
                    "from 0 to 65536, got <many>"),
            std::string::npos);
  // The value prm/step-4.prm sets too, for its reduced contact model.
  EXPECT_EQ(defaults.response_tolerance, 1e-7);
}


// ----------------------------------------------------------------------------
// The fuzzy contact model: reduced pipeline against the exact solver
// ----------------------------------------------------------------------------

#include <fuzzycontact/output/fuzzy_report.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

namespace
{

  // The coarse meshes of the scenes (1510 DoFs per component) and an FL2C
  // tolerance far below the differences the tests look at.
  // The default outputs: the slave node's u_x, u_y, F_n, F_t.
  const std::vector<std::string> default_outputs =
    Observations::split(Observations::default_outputs());

  FuzzyContactModelSettings
  coarse_settings()
  {
    FuzzyContactModelSettings s;
    s.mesh_refinements = 0;
    s.fl2c.tolerance   = 1e-10;
    return s;
  }

  const std::string default_study = R"(
set fuzzy parameters = P1.E, P2.E, P1.tip.force
subsection Fuzzy parameter P1.E
  set values   = 0.95, 1, 1.05
  set relative = true
end
subsection Fuzzy parameter P2.E
  set values   = 0.95, 1, 1.05
  set relative = true
end
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
)";

  // The corners of the support box and its centre.
  std::vector<std::vector<double>>
  corners_and_centre(const FuzzyParameterSet &set)
  {
    std::vector<std::vector<double>> points;
    const auto                       box = alpha_box(set.numbers(), 0);
    for (unsigned long c = 0; c < (1ul << box.size()); ++c)
      {
        std::vector<double> p;
        for (unsigned int d = 0; d < box.size(); ++d)
          p.push_back((c >> d) & 1 ? box[d].upper : box[d].lower);
        points.push_back(p);
      }
    std::vector<double> centre;
    for (const Interval &i : box)
      centre.push_back(i.midpoint());
    points.push_back(centre);
    return points;
  }

  double
  largest_difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    // ux, uy relative to |uy|, Fn and Ft relative to Fn
    const double u = std::abs(b[1]), f = std::abs(b[2]);
    return std::max({std::abs(a[0] - b[0]) / u,
                     std::abs(a[1] - b[1]) / u,
                     std::abs(a[2] - b[2]) / f,
                     std::abs(a[3] - b[3]) / f});
  }
} // namespace

// Whole-beam moduli scale the stiffness exactly and the static correction
// makes the reduced model exact: the reduced pipeline must reproduce the
// exact full-order answers to the FL2C and back-substitution accuracy, over
// the whole support box, with friction (mu = 0.3 in the scene).
TEST(FuzzyContactModel, ReducedMatchesFullOrderForTheDefaultStudy)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, default_study);
  FuzzyContactModel       model(scene, set, default_outputs, coarse_settings());
  for (const auto &p : corners_and_centre(set))
    {
      const auto r = model.reduced(p);
      const auto f = model.full_order(p);
      EXPECT_LT(largest_difference(r, f), 1e-7);
      // the load is 10 to 100 kN: F_n is about 8/9 of it
      EXPECT_NEAR(f[2] / p[2], 0.9, 0.05);
    }
  EXPECT_EQ(model.reanalysis_orders(), (std::vector<unsigned int>{0, 0}));
}

// A solver that fails at one point of the study says which point, which
// model and which keys control it.
TEST(FuzzyContactModel, AFailedEvaluationNamesThePointAndTheKeys)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, default_study);
  FuzzyContactModelSettings settings = coarse_settings();
  settings.fl2c.max_iterations       = 1;
  FuzzyContactModel model(scene, set, default_outputs, settings);
  const std::string message = error_of([&]() {
    model.reduced({2.1e11, 2.1e11, 5e4});
  });
  EXPECT_NE(message.find("At the parameter point P1.E = 2.1e+11, P2.E = "
                         "2.1e+11, P1.tip.force = 50000, the reduced model "
                         "(FL2C):"),
            std::string::npos)
    << message;
  EXPECT_NE(message.find("did not converge in 1 iterations"), std::string::npos)
    << message;
  EXPECT_NE(message.find("subsection FL2C"), std::string::npos) << message;
}

// The model's description says how often each body's mesh was refined
// (a mesh file is refined by the key's default too) and into how many
// cells: a refinement makes four of every cell.
TEST(FuzzyContactModel, TheDescriptionSaysHowOftenTheMeshWasRefined)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, default_study);
  FuzzyContactModelSettings settings = coarse_settings();
  const FuzzyContactModel   coarse(scene, set, default_outputs, settings);
  settings.mesh_refinements = 1;
  const FuzzyContactModel refined(scene, set, default_outputs, settings);
  EXPECT_EQ(coarse.describe().find("refined"), std::string::npos)
    << coarse.describe();
  const Component    unrefined(scene.components[0], scene.plane_model, 0);
  const unsigned int cells = unrefined.triangulation().n_active_cells();
  EXPECT_NE(refined.describe().find(
              scene.components[0].name + ": " +
              std::to_string(
                Component(scene.components[0], scene.plane_model, 1).n_dofs()) +
              " DoFs (" + std::to_string(4 * cells) +
              " cells: its mesh refined 1 time(s), key 'mesh refinements')"),
            std::string::npos)
    << refined.describe();
}

// Moduli of whole bodies and loads only: the study needs no modes (the
// static correction alone is exact), skips the modal analysis and says so;
// with the modes forced the answers are the same to the solver accuracy.
TEST(FuzzyContactModel, SkipsTheModesWhenTheStaticCorrectionIsExact)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, default_study);
  FuzzyContactModelSettings settings = coarse_settings();
  FuzzyContactModel         without(scene, set, default_outputs, settings);
  settings.modes_when_needed = false;
  FuzzyContactModel with(scene, set, default_outputs, settings);
  EXPECT_NE(without.skipped().find("no modal analysis"), std::string::npos);
  EXPECT_NE(without.describe().find("no modes"), std::string::npos);
  EXPECT_TRUE(with.skipped().empty());
  EXPECT_EQ(with.describe().find("no modes"), std::string::npos);
  for (const auto &p : corners_and_centre(set))
    {
      const auto f = without.full_order(p);
      EXPECT_LT(largest_difference(without.reduced(p), f), 1e-7);
      EXPECT_LT(largest_difference(with.reduced(p), f), 1e-7);
    }
}

// Zone moduli change the mode shapes: the modes are re-analysed by HPTP and
// the static correction modes stay nominal, so the reduced answer is
// approximate away from the nominal point; at the nominal point it is exact.
// The other body, whose stiffness keeps its shape, gets no modes.
TEST(FuzzyContactModel, ZoneParametersGoThroughTheReanalysis)
{
  Scene scene = Scene::read(source_dir + "/prm/overlap.prm");
  // P1 in two zones; x = 0.08 is a mesh line (30 of 75 cells).
  scene.components[0].implicit_zone = false;
  scene.components[0].zones         = {
            MaterialZone{"root", {{0, 0.08}}, {{-1, 1}}, 210e9, 0.3, 7900},
            MaterialZone{"rest", {{0.08, 0.2}}, {{-1, 1}}, 210e9, 0.3, 7900}};
  const FuzzyParameterSet set    = fuzzy_parameters(scene, R"(
set fuzzy parameters = P1.root.E, P1.rest.rho
subsection Fuzzy parameter P1.root.E
  set values   = 0.9, 1, 1.1
  set relative = true
end
subsection Fuzzy parameter P1.rest.rho
  set values   = 0.9, 1, 1.1
  set relative = true
end
)");
  const auto              points = corners_and_centre(set);
  const auto              centre = points.back();
  double                  worst_of[3];
  for (const auto correction :
       {ReducedModelSettings::ZoneCorrection::residual_flexibility,
        ReducedModelSettings::ZoneCorrection::galerkin,
        ReducedModelSettings::ZoneCorrection::krylov})
    {
      FuzzyContactModelSettings settings = coarse_settings();
      settings.reduced.zone_correction   = correction;
      FuzzyContactModel model(scene, set, default_outputs, settings);
      const bool        krylov =
        correction == ReducedModelSettings::ZoneCorrection::krylov;
      // The Krylov static correction needs no modes: no HPTP either.
      EXPECT_EQ(model.reanalysis_orders()[0] >= 1, !krylov);
      EXPECT_EQ(model.reanalysis_orders()[1], 0u);
      EXPECT_NE(model.describe().find(krylov ? "re-analysed by Krylov vectors"
                                             : "parameter-independent HPTP"),
                std::string::npos)
        << model.describe();
      // P2's stiffness keeps its shape: no modes for it (the static
      // correction is exact there), and the model says so.
      EXPECT_NE(model.skipped().find(
                  krylov ? "P2: no fuzzy parameter changes the shape of its "
                           "stiffness"
                         : "no modal analysis of P2"),
                std::string::npos)
        << model.skipped();
      EXPECT_NE(model.describe().find("P2: 1510 DoFs, no modes"),
                std::string::npos)
        << model.describe();

      // exact at the nominal point
      EXPECT_LT(largest_difference(model.reduced(centre),
                                   model.full_order(centre)),
                1e-7);
      double &worst = worst_of[static_cast<int>(correction)];
      worst         = 0;
      for (const auto &p : points)
        worst =
          std::max(worst,
                   largest_difference(model.reduced(p), model.full_order(p)));
      if (!krylov)
        {
          EXPECT_GT(worst, 1e-9); // an approximation away from it
        }
    }
  // Measured on this mesh at +-10 % of the root modulus and of the density
  // (u_x relative to u_y here): the residual flexibility kept nominal
  // gives 1.2e-5 (1e-6 for u_y and F_n, 2e-4 for u_x relative to itself);
  // the Galerkin projection onto [T Y(p), Psi] 3e-7; the Krylov static
  // correction (tolerance 1e-8 on the contact flexibility) the exact
  // answer to the solvers' accuracy.
  EXPECT_LT(worst_of[0], 5e-5);
  EXPECT_LT(worst_of[1], 2e-6);
  EXPECT_LT(worst_of[1], worst_of[0]);
  EXPECT_LT(worst_of[2], 1e-8);
}


// A level where no point had outputs (no equilibrium anywhere in its box,
// or every point left out near the limit of sliding) has no bound and no
// argument: nothing to prove, so it is not unproven either (the proofs'
// feedback once asked for an exact snapshot at the empty point, and the
// study stopped). The level with a bound is judged as before.
TEST(ProofFeedback, ALevelWithoutABoundHasNothingToProve)
{
  const double      nan = std::numeric_limits<double>::quiet_NaN();
  FuzzyOutputBounds b;
  b.bounds = {{Interval{1., 2.}, Interval{nan, nan}}};
  b.argmin = {{{0.1}, {}}};
  b.argmax = {{{0.2}, {}}};
  BoundProofs p;
  p.lower = {{BoundProof{1., 1.5}, BoundProof{nan, nan}}};
  p.upper = {{BoundProof{2., 2.}, BoundProof{nan, nan}}};
  const std::vector<UnprovenBound> u = unproven_bounds(b, p, 1e-4, 1e-7);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].level, 0u);
  EXPECT_FALSE(u[0].upper);
  EXPECT_EQ(u[0].argument, std::vector<double>{0.1});
}

// The proofs feed back (fuzzy/proof_feedback.h): a deliberately poor model
// (three modes, no static correction) leaves the bounds of the default
// study far beyond 1e-4 of their range at their arguments; made richer by
// the exact solutions there, round after round, every bound ends proven
// within the tolerance. Without rounds (max rounds = 0) the same bounds
// stay unproven and are listed, with their errors.
TEST(ProofFeedback, APoorModelIsCorrectedUntilProven)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, default_study);
  FuzzyContactModelSettings settings = coarse_settings();
  settings.reduced.static_correction = false;
  settings.modal.n_modes             = 3;
  const std::vector<double> alpha    = {0., 0.5, 1.};
  for (const unsigned int max_rounds : {0u, 4u})
    {
      FuzzyContactModel model(scene, set, default_outputs, settings);
      model.set_reuse_factorisations(true);
      const Response reduced = [&](const std::vector<double> &p) {
        return model.reduced(p);
      };
      const Response exact = [&](const std::vector<double> &p) {
        return model.full_order(p);
      };
      ProofSettings ps;
      ps.max_rounds             = max_rounds;
      const ProvenBounds proven = prove_and_correct(
        [&]() {
          return OptimisationMethod().bounds(model.effective_numbers(),
                                             alpha,
                                             reduced,
                                             default_outputs,
                                             self);
        },
        [&](const FuzzyOutputBounds &b) {
          return prove_bounds(b, exact, self);
        },
        [&](const std::vector<std::vector<double>> &points) {
          return model.enrich(points);
        },
        ps);
      ASSERT_FALSE(proven.rounds.empty());
      EXPECT_GT(proven.rounds[0].largest, 1e-2); // the poor model
      EXPECT_GT(proven.rounds[0].n_unproven, 0u);
      if (max_rounds == 0)
        {
          EXPECT_EQ(proven.rounds.size(), 1u);
          EXPECT_EQ(proven.unproven.size(), proven.rounds[0].n_unproven);
          EXPECT_NE(proven.stopped.find("max rounds = 0"), std::string::npos);
          for (const UnprovenBound &u : proven.unproven)
            {
              const BoundProof &p = u.upper
                                      ? proven.proofs.upper[u.output][u.level]
                                      : proven.proofs.lower[u.output][u.level];
              EXPECT_EQ(u.difference, p.difference());
              EXPECT_GT(u.relative, ps.tolerance);
            }
          continue;
        }
      EXPECT_TRUE(proven.unproven.empty()) << proven.stopped;
      EXPECT_GT(proven.rounds.size(), 1u);
      EXPECT_GT(proven.rounds[0].added, 0u);
      EXPECT_EQ(proven.stopped, "every bound proven");
      EXPECT_LE(proven.rounds.back().largest, ps.tolerance);
      // The proven bounds against the exact values at the vertices (the
      // response is monotone: the vertex method on the exact model is the
      // answer).
      const FuzzyOutputBounds truth =
        VertexMethod().bounds(model.effective_numbers(),
                              alpha,
                              exact,
                              default_outputs,
                              self);
      for (unsigned int k = 0; k < 4; ++k)
        {
          const double range = proof_range(proven.bounds, proven.proofs, k);
          for (unsigned int l = 0; l < alpha.size(); ++l)
            {
              EXPECT_NEAR(proven.bounds.bounds[k][l].lower,
                          truth.bounds[k][l].lower,
                          ps.tolerance * range)
                << k << " " << l;
              EXPECT_NEAR(proven.bounds.bounds[k][l].upper,
                          truth.bounds[k][l].upper,
                          ps.tolerance * range)
                << k << " " << l;
            }
        }
    }
}

// A density cannot change a static answer: the model says so, does not
// vary it (no modes are needed for it), answers the same bits whatever its
// value, and the numbers to propagate make it crisp, so every interval
// method gives outputs that are crisp in it (before, a fuzzy zone density
// gave u_x a spurious interval of its reduction error).
TEST(FuzzyContactModel, ADensityIsInertAndGivesCrispOutputs)
{
  Scene scene = Scene::read(source_dir + "/prm/overlap.prm");
  scene.components[0].implicit_zone = false;
  scene.components[0].zones         = {
            MaterialZone{"root", {{0, 0.08}}, {{-1, 1}}, 210e9, 0.3, 7900},
            MaterialZone{"rest", {{0.08, 0.2}}, {{-1, 1}}, 210e9, 0.3, 7900}};
  const FuzzyParameterSet set = fuzzy_parameters(scene, R"(
set fuzzy parameters = P1.rest.rho, P1.tip.force
subsection Fuzzy parameter P1.rest.rho
  set values   = 0.6, 1, 1.4
  set relative = true
end
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
)");
  FuzzyContactModel       model(scene, set, default_outputs, coarse_settings());
  ASSERT_EQ(model.inert().size(), 2u);
  EXPECT_NE(model.inert()[0].find("a density"), std::string::npos);
  EXPECT_TRUE(model.inert()[1].empty());
  EXPECT_NE(model.skipped().find("no modal analysis"), std::string::npos);
  const auto light = model.reduced({0.6 * 7900, 5e4});
  EXPECT_EQ(model.reduced({1.4 * 7900, 5e4}), light);
  EXPECT_LT(largest_difference(light, model.full_order({1.4 * 7900, 5e4})),
            1e-7);

  const std::vector<FuzzyNumber> numbers = model.effective_numbers();
  EXPECT_EQ(numbers[0].alpha_cut(0).width(), 0.);
  EXPECT_EQ(numbers[1].alpha_cut(0).width(), 90e3);
  const Response reduced = [&](const std::vector<double> &p) {
    return model.reduced(p);
  };
  const auto o = OptimisationMethod().bounds(numbers,
                                             {0., 1.},
                                             reduced,
                                             {"ux", "uy", "Fn", "Ft"},
                                             self);
  for (unsigned int k = 0; k < 4; ++k)
    {
      EXPECT_EQ(o.argmin[k][0][0], 7900.);
      EXPECT_EQ(o.argmax[k][0][0], 7900.);
      // the core (a point) is crisp: its bounds are one value
      EXPECT_EQ(o.bounds[k][1].lower, o.bounds[k][1].upper);
    }
}

TEST(FuzzyContactModel, FrictionAndGapParameters)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, R"(
set fuzzy parameters = interface.mu, interface.gap
subsection Fuzzy parameter interface.mu
  set values = 0, 0.3, 0.6
end
subsection Fuzzy parameter interface.gap
  set values = 0, 1e-8, 1e-4
end
)");
  FuzzyContactModel       model(scene, set, default_outputs, coarse_settings());
  for (const auto &p : corners_and_centre(set))
    EXPECT_LT(largest_difference(model.reduced(p), model.full_order(p)), 1e-7);
  // a larger gap lowers the contact force; no friction, no tangential force
  const auto open   = model.full_order({0.3, 1e-4});
  const auto closed = model.full_order({0.3, 0.});
  EXPECT_LT(open[2], closed[2]);
  EXPECT_EQ(model.full_order({0., 1e-8})[3], 0.);
}

// The two exact references agree, and every evaluation is a pure function
// of its parameters (the order of evaluation, and so the number of MPI
// ranks, does not change a single bit).
TEST(FuzzyContactModel, ReferencesAgreeAndEvaluationsArePure)
{
  const Scene             scene = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, default_study);
  FuzzyContactModel independent(scene, set, default_outputs, coarse_settings());
  FuzzyContactModel reusing(scene, set, default_outputs, coarse_settings());
  reusing.set_reuse_factorisations(true);
  const auto points = corners_and_centre(set);
  for (const auto &p : points)
    EXPECT_LT(largest_difference(reusing.full_order(p),
                                 independent.full_order(p)),
              1e-8);
  for (FuzzyContactModel *m : {&independent, &reusing})
    {
      const auto a = m->reduced(points[0]);
      const auto b = m->full_order(points[0]);
      m->reduced(points[5]);
      m->full_order(points[5]);
      EXPECT_EQ(m->reduced(points[0]), a);
      EXPECT_EQ(m->full_order(points[0]), b);
    }
}

// A fuzzy load beside another non-zero load (on the other body, pressing
// P2's free end down), and a fuzzy load whose declared force is zero: every
// load enters with its own force, in both models alike.
TEST(FuzzyContactModel, EveryLoadHasItsOwnForce)
{
  Scene scene = Scene::read(source_dir + "/prm/overlap.prm");
  scene.components[1].loads.push_back(
    EdgeLoad{"extra", "left", 5e3, dealii::Tensor<1, 2>({0., -1.})});
  scene.components[1].loads.push_back(
    EdgeLoad{"lift", "left", 0., dealii::Tensor<1, 2>({0., 1.})});
  const FuzzyParameterSet set = fuzzy_parameters(scene, R"(
set fuzzy parameters = P1.tip.force, P2.lift.force
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
subsection Fuzzy parameter P2.lift.force
  set values = 0, 1e3, 4e3
end
)");
  FuzzyContactModel       model(scene, set, default_outputs, coarse_settings());
  FuzzyContactModel reusing(scene, set, default_outputs, coarse_settings());
  reusing.set_reuse_factorisations(true);
  for (const auto &p : corners_and_centre(set))
    {
      const auto f = model.full_order(p);
      EXPECT_LT(largest_difference(model.reduced(p), f), 1e-7);
      EXPECT_LT(largest_difference(reusing.full_order(p), f), 1e-8);
    }
  // Superposition: without contact changes (P1's tip stays closed) the
  // load on P2 lowers F_n; lifting P2 by as much as P2.extra pushes it
  // down leaves the answer of a scene without either.
  const auto both   = model.full_order({50e3, 0.});
  const auto lifted = model.full_order({50e3, 4e3});
  EXPECT_LT(both[2], lifted[2]);
  Scene                   plain = Scene::read(source_dir + "/prm/overlap.prm");
  const FuzzyParameterSet plain_set = fuzzy_parameters(plain, R"(
set fuzzy parameters = P1.tip.force
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
)");
  FuzzyContactModel       plain_model(plain,
                                plain_set,
                                default_outputs,
                                coarse_settings());
  const auto              without  = plain_model.full_order({50e3});
  const auto              balanced = model.full_order({50e3, 5e3});
  EXPECT_LT(largest_difference(balanced, without), 1e-9);
}

// The modulus of a body that a prescribed displacement drives: the forces
// that impose the displacement scale with the body's stiffness, in every
// model. The contact patch test on matching meshes (prm/patch-test.prm with
// 5 x 3 cells on both blocks) is exact to round-off, so every model must
// give the two blocks in series under the displacement delta of the upper
// block's top (plane strain, uniaxial stress):
//     sigma = delta / (H_1 / E_1' + H_2 / E_2'),  E' = E / (1 - nu^2),
// F_n = sigma * width * t, and the interface's u_y = -sigma H_2 / E_2'.
TEST(FuzzyContactModel, ModulusOfABodyDrivenByADisplacement)
{
  Scene scene = Scene::read(source_dir + "/prm/patch-test.prm");
  scene.components[0].subdivisions       = {{5, 3}};
  const FuzzyParameterSet        set     = fuzzy_parameters(scene, R"(
set fuzzy parameters = Upper.E, Lower.E, Upper.press.displacement
subsection Fuzzy parameter Upper.E
  set values   = 0.5, 1, 2
  set relative = true
end
subsection Fuzzy parameter Lower.E
  set values   = 0.8, 1, 1.25
  set relative = true
end
subsection Fuzzy parameter Upper.press.displacement
  set values = 0.5e-5, 1e-5, 2e-5
end
)");
  const std::vector<std::string> outputs = {"Fn", "Lower.node(0.1, 0.05).uy"};
  FuzzyContactModel independent(scene, set, outputs, coarse_settings());
  FuzzyContactModel reusing(scene, set, outputs, coarse_settings());
  reusing.set_reuse_factorisations(true);
  const double nu = 0.3, H = 0.05, width = 0.1;
  for (const auto &p : corners_and_centre(set)) // E_1, E_2 [Pa], delta [m]
    {
      const double E1 = p[0] / (1 - nu * nu), E2 = p[1] / (1 - nu * nu);
      const double sigma  = p[2] / (H / E1 + H / E2);
      const double Fn     = sigma * width;
      const double uy     = -sigma * H / E2;
      const auto   exact  = independent.full_order(p);
      const auto   reused = reusing.full_order(p);
      const auto   fast   = independent.reduced(p);
      for (const auto *v : {&exact, &reused, &fast})
        {
          EXPECT_NEAR((*v)[0], Fn, 1e-9 * Fn);
          EXPECT_NEAR((*v)[1], uy, 1e-9 * std::abs(uy));
        }
    }
  // A zone's own modulus would change the shape of those forces, which the
  // re-analysed reduced models do not follow: refused, naming the way out.
  scene.components[0].zones.push_back(scene.components[0].zones[0]);
  scene.components[0].zones[0].name = "core";
  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("Upper.core.E", scene);
            }).find("Vary the modulus of the whole body (Upper.E)"),
            std::string::npos);
}

// With gravity a density is no longer inert: it scales the weight of its
// zones. The column on its footing (prm/column.prm) with two density
// layers in the column: a zone density (Column.upper.rho), a body's
// density (Footing.rho) and the moduli of both bodies. At the corners of
// the box and its centre, the reduced model (FL2C and the exact reduced
// solver: the weight's exact zone responses, scaled by the densities and
// 1/s), the independent full-order analyses and the reusing reference
// (its factorisations stay: the densities do not change the stiffness)
// all give the uniaxial closed form.
TEST(FuzzyContactModel, DensitiesScaleTheWeightUnderGravity)
{
  Scene scene = Scene::read(source_dir + "/prm/column.prm");
  scene.components[0].implicit_zone = false;
  scene.components[0].zones         = {
            MaterialZone{"lower", {{0, 0.1}}, {{0.2, 0.7}}, 210e9, 0.3, 7900},
            MaterialZone{"upper", {{0, 0.1}}, {{0.7, 1.2}}, 210e9, 0.3, 7900}};
  const FuzzyParameterSet        set     = fuzzy_parameters(scene, R"(
set fuzzy parameters = Column.upper.rho, Footing.rho, Column.E, Footing.E
subsection Fuzzy parameter Column.upper.rho
  set values   = 0.5, 1, 2
  set relative = true
end
subsection Fuzzy parameter Footing.rho
  set values = 2000, 2400, 2800
end
subsection Fuzzy parameter Column.E
  set values   = 0.9, 1, 1.1
  set relative = true
end
subsection Fuzzy parameter Footing.E
  set values   = 0.8, 1, 1.25
  set relative = true
end
)");
  const std::vector<std::string> outputs = {"Fn",
                                            "Column.node(0.05, 1.2).uy",
                                            "Footing.node(0.05, 0.2).uy"};
  FuzzyContactModel independent(scene, set, outputs, coarse_settings());
  FuzzyContactModel reusing(scene, set, outputs, coarse_settings());
  reusing.set_reuse_factorisations(true);
  for (const std::string &why : independent.inert())
    EXPECT_TRUE(why.empty()) << why;
  EXPECT_EQ(independent.reanalysis_orders(), (std::vector<unsigned int>{0, 0}));
  for (const auto &p : corners_and_centre(set))
    {
      const auto exact = column_closed_form(scene, set.state(scene, p));
      for (const auto &v : {independent.full_order(p),
                            reusing.full_order(p),
                            independent.reduced(p),
                            independent.reduced(p, ActiveSetSolver())})
        {
          EXPECT_NEAR(v[0], exact[0], 1e-10 * exact[0]);
          EXPECT_NEAR(v[1], exact[2], 1e-9 * std::abs(exact[2]));
          EXPECT_NEAR(v[2], exact[1], 1e-9 * std::abs(exact[1]));
        }
    }
}

// Issue 19's case: a fuzzy clearance (1e-6, 5e-3, 30e-3 m) with a fuzzy
// tip load (10, 50, 100 kN). On prm/stacked.prm F_t is mu F_n at the
// touching tip, monotone (every bound at a vertex); its kinks come with a
// push along P1 that makes friction reverse inside the range of the load,
// as on prm/kinked.prm, here on coarse meshes with ROL held to 10
// iterations as in prm/step-4-kinked.prm. F_t's largest value over the
// alpha = 0.25 box lies at the kink where the contact starts to stick, a
// curve in the gap and the load. The bound must be within 1e-3 of the range
// of a dense reference of the same reduced model (per load the largest of
// 101 gaps refined by golden-section search, over 101 loads refined
// likewise), attained where it says, and called converged.
TEST(FuzzyContactModel, KinkedMaximumOfAFuzzyClearanceAgainstADenseReference)
{
  const Scene               scene = Scene::read(source_dir + "/prm/kinked.prm");
  const FuzzyParameterSet   set   = fuzzy_parameters(scene, R"(
set fuzzy parameters = interface.gap, P1.tip.force
subsection Fuzzy parameter interface.gap
  set values = 1e-6, 5e-3, 30e-3
end
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
)");
  FuzzyContactModelSettings model_settings = coarse_settings();
  model_settings.fl2c.tolerance            = 1e-9;
  FuzzyContactModel model(scene, set, {"Ft"}, model_settings);
  const Response    reduced = [&](const std::vector<double> &p) {
    return model.reduced(p);
  };
  OptimisationSettings settings;
  settings.max_iterations = 10;
  const auto alpha        = alpha_levels(5);
  const auto o            = OptimisationMethod(settings).bounds(set.numbers(),
                                                     alpha,
                                                     reduced,
                                                     {"Ft"},
                                                     self);
  ASSERT_EQ(alpha[1], 0.25);

  // The dense reference over the alpha = 0.25 box: for each of 101 loads,
  // the best of 101 gaps refined by a golden-section search between its
  // neighbours (F_t is unimodal in the gap there: it rises to the kink
  // where the contact starts to stick); then the same in the load around
  // the best of them.
  const auto box = alpha_box(set.numbers(), 0.25);
  const auto golden =
    [](const std::function<double(double)> &phi, double a, double b) {
      const double r = (std::sqrt(5.) - 1) / 2;
      double       c = b - r * (b - a), d = a + r * (b - a);
      double       fc = phi(c), fd = phi(d);
      for (unsigned int i = 0; i < 60 && b - a > 1e-12 * std::abs(b); ++i)
        if (fc > fd)
          {
            b  = d;
            d  = c;
            fd = fc;
            c  = b - r * (b - a);
            fc = phi(c);
          }
        else
          {
            a  = c;
            c  = d;
            fc = fd;
            d  = a + r * (b - a);
            fd = phi(d);
          }
      return std::max(fc, fd);
    };
  // The largest of @p phi over @p range: 101 points, then golden section
  // between the best one's neighbours.
  const auto largest = [&](const std::function<double(double)> &phi,
                           const Interval                      &range) {
    double       best = -std::numeric_limits<double>::infinity();
    unsigned int at   = 0;
    for (unsigned int i = 0; i <= 100; ++i)
      {
        const double v = phi(range.lower + range.width() * i / 100);
        if (v > best)
          {
            best = v;
            at   = i;
          }
      }
    return std::max(
      best,
      golden(phi,
             range.lower + range.width() * (at > 0 ? at - 1 : 0) / 100,
             range.lower + range.width() * std::min(at + 1, 100u) / 100));
  };
  double     lowest  = std::numeric_limits<double>::infinity();
  const auto at_load = [&](const double load) {
    return largest(
      [&](const double gap) {
        const double v = model.reduced({gap, load})[0];
        lowest         = std::min(lowest, v);
        return v;
      },
      box[0]);
  };
  const double best  = largest(at_load, box[1]);
  const double range = best - lowest;
  const double upper = o.bounds[0][1].upper;
  EXPECT_GT(upper, best - 1e-3 * range)
    << "short of the dense reference by " << (best - upper) / range
    << " of the range";
  EXPECT_EQ(model.reduced(o.argmax[0][1])[0], upper);
  EXPECT_TRUE(o.upper_quality[0][1].converged)
    << o.upper_quality[0][1].n_starts << " starts, "
    << o.upper_quality[0][1].n_agree << " agree";
}

// A block on a 20-degree slope held by friction alone (prm/slope.prm), its
// friction coefficient fuzzy (0.3, 0.4, 0.5) around statics' critical
// tan 20 deg = 0.36397 and its load fuzzy: below tan 20 there is no static
// equilibrium, a result of the point in both models (no outputs), which
// has_static_equilibrium() tells without a solve. The fuzzy output
// "sliding possible" has the membership of tan 20 in the friction
// coefficient, (tan 20 - 0.3) / 0.1 = 0.63970 (to 1e-6: the equilibrium
// check's NNLS decides to 1e-8 of the load), where it starts at mu =
// tan 20. Over the part of every box with an equilibrium F_n = F cos 20
// (statics), so the bounds of every method are those of the load times
// cos 20, found at points with an equilibrium.
TEST(FuzzyContactModel, SlidingInsideTheFuzzyRange)
{
  const Scene             scene = Scene::read(source_dir + "/prm/slope.prm");
  const FuzzyParameterSet set   = fuzzy_parameters(scene, R"(
set fuzzy parameters = block-on-slope.mu, Block.weight.force
subsection Fuzzy parameter block-on-slope.mu
  set values = 0.3, 0.4, 0.5
end
subsection Fuzzy parameter Block.weight.force
  set values = 5e3, 1e4, 2e4
end
)");
  FuzzyContactModel       model(scene, set, {"Fn"}, coarse_settings());
  EXPECT_TRUE(model.can_lose_equilibrium());
  EXPECT_EQ(model.bodies_held_by_contact(), "Block");
  const double theta = 20 * M_PI / 180, t = std::tan(theta);
  for (const double mu : {0.3, t - 1e-6, t + 1e-6, 0.5})
    {
      const bool holds = mu > t;
      EXPECT_EQ(model.has_static_equilibrium({mu, 1e4}), holds) << mu;
      EXPECT_EQ(has_solution(model.reduced({mu, 1e4})), holds) << mu;
      EXPECT_EQ(has_solution(model.full_order({mu, 1e4})), holds) << mu;
    }

  const auto           numbers = model.effective_numbers();
  const auto           alpha   = alpha_levels(5);
  const FeasibleRegion region  = feasible_region(
    numbers,
    alpha,
    [&](const std::vector<double> &p) {
      return model.has_static_equilibrium(p);
    },
    32);
  EXPECT_TRUE(region.possible);
  EXPECT_TRUE(region.vertices_decide);
  EXPECT_NEAR(region.membership, (t - 0.3) / 0.1, 1e-6);
  ASSERT_EQ(region.starts_at.size(), 2u);
  EXPECT_NEAR(region.starts_at[0], t, 1e-7);
  for (unsigned int l = 0; l < alpha.size(); ++l)
    {
      EXPECT_EQ(region.levels[l].possible, alpha[l] < 0.6397) << alpha[l];
      if (region.levels[l].possible)
        {
          // along mu from the vertex without equilibrium: at tan 20
          ASSERT_FALSE(region.levels[l].boundary.empty());
          EXPECT_EQ(region.levels[l].boundary[0].parameter, 0u);
          EXPECT_NEAR(region.levels[l].boundary[0].point[0], t, 1e-7);
        }
    }

  const Response reduced = [&](const std::vector<double> &p) {
    return model.reduced(p);
  };
  std::vector<FuzzyOutputBounds> methods;
  methods.push_back(
    OptimisationMethod().bounds(numbers, alpha, reduced, {"Fn"}, self));
  methods.push_back(
    VertexMethod().bounds(numbers, alpha, reduced, {"Fn"}, self));
  methods.push_back(
    ExtensionPrinciple(3).bounds(numbers, alpha, reduced, {"Fn"}, self));
  for (const FuzzyOutputBounds &b : methods)
    for (unsigned int l = 0; l < alpha.size(); ++l)
      {
        const auto load = alpha_box(numbers, alpha[l])[1];
        EXPECT_NEAR(b.bounds[0][l].lower,
                    load.lower * std::cos(theta),
                    1e-8 * 2e4);
        EXPECT_NEAR(b.bounds[0][l].upper,
                    load.upper * std::cos(theta),
                    1e-8 * 2e4);
        EXPECT_GE(b.argmin[0][l][0], t);
        EXPECT_GE(b.argmax[0][l][0], t);
        EXPECT_EQ(b.n_infeasible[l] > 0, alpha[l] < 0.6397) << alpha[l];
      }
}

namespace
{
  // The results of one output "Fn" at alpha = 0: its bounds, proven exact
  // there, and the Extension Principle's interval.
  FuzzyStudyResults
  one_output_results(const Interval &bounds, const Interval &reference)
  {
    FuzzyStudyResults r;
    r.outputs.resize(1);
    r.outputs[0].name         = "Fn";
    r.alpha                   = {0.};
    r.has_reference           = true;
    r.has_proofs              = true;
    r.proof_settings.accuracy = 1e-7;
    r.optimisation.bounds     = {{bounds}};
    r.reference.bounds        = {{reference}};
    r.proofs.lower            = {{BoundProof{bounds.lower, bounds.lower}}};
    r.proofs.upper            = {{BoundProof{bounds.upper, bounds.upper}}};
    return r;
  }
} // namespace

// Evaluations near the limit of equilibrium that the contact solver could
// not answer were left out of the bounds: the report says so in a warning
// line with their number, and results.json counts them; none, no warning.
TEST(FuzzyStudyReport, PointsLeftOutNearTheLimitAreAWarning)
{
  for (const unsigned long n : {0ul, 3ul})
    {
      FuzzyStudyResults r =
        one_output_results(Interval{0., 1.}, Interval{0., 1.});
      r.has_equilibrium                = true;
      r.unanswered.unsolved_near_limit = n;
      nlohmann::json    json;
      const std::string text = FuzzyStudyReport::equilibrium(r, json);
      EXPECT_EQ(text.find("warning: 3 evaluation(s) near the limit of "
                          "equilibrium (the loads need more than 95 % of "
                          "the friction) failed in the contact solver") !=
                  std::string::npos,
                n > 0)
        << text;
      EXPECT_EQ(text.find("warning:") != std::string::npos, n > 0) << text;
      EXPECT_EQ(json["static_equilibrium"]["n_unsolved_near_limit"]
                  .get<unsigned long>(),
                n);
    }
}

// A bound short of the Extension Principle's sample by more than the
// proofs' tolerance is not the optimum, whatever its search said: the
// report says so in a warning line, and results.json flags it and calls
// the output not converged. Synthetic results: an upper bound of 1.5 (exact
// there too) where the reference sampled 2, on a range of 2.
TEST(FuzzyStudyReport, ABoundShortOfTheReferenceIsAWarning)
{
  for (const double sampled : {2.0, 1.5})
    {
      FuzzyStudyResults r =
        one_output_results(Interval{0., 1.5}, Interval{0., sampled});
      std::ostringstream out;
      nlohmann::json     entry;
      entry["converged"] = true;
      FuzzyStudyReport::comparison(r, 0, out, entry);
      const bool short_of = sampled > 1.5;
      EXPECT_EQ(out.str().find("warning: Fn: 1 bound(s) fall short of the "
                               "Extension Principle's sampled interval") !=
                  std::string::npos,
                short_of)
        << out.str();
      EXPECT_EQ(entry["converged"].get<bool>(), !short_of);
      EXPECT_EQ(entry["reference_comparison"]["short_bounds"].size(),
                short_of ? 1u : 0u);
      if (short_of)
        {
          EXPECT_DOUBLE_EQ(
            entry["reference_comparison"]["short_bounds"][0]["short"]
              .get<double>(),
            0.25);
        }
    }
  // A crisp output (a total force statics fixes: its range is round-off):
  // short of the sample by 2e-9 of its range of 4e-9, within 1e-7 of its
  // magnitude, is no warning.
  FuzzyStudyResults r =
    one_output_results(Interval{1e5, 1e5 + 2e-9}, Interval{1e5, 1e5 + 4e-9});
  std::ostringstream out;
  nlohmann::json     entry;
  FuzzyStudyReport::comparison(r, 0, out, entry);
  EXPECT_EQ(out.str().find("warning:"), std::string::npos) << out.str();
  EXPECT_TRUE(entry["reference_comparison"]["short_bounds"].empty());
  // And the report says why: the shortfall (half the range) is round-off.
  EXPECT_NE(out.str().find("short of it by at most 5.0e-01 (2.0e-09 in the "
                           "output's units: within its accuracy"),
            std::string::npos)
    << out.str();
}

// A bound beyond the Extension Principle's interval only by the reduction
// error (the exact value at its argument is not beyond it) is said to be;
// for a crisp output, whose range is round-off, the report adds that the
// excess is within the output's accuracy, and only then.
TEST(FuzzyStudyReport, BeyondTheReferenceOnlyByRoundOffIsSaidToBe)
{
  for (const double scale : {1e-9, 1.})
    {
      // Upper bound 1e5 + 6 scale (reduced; exact there 1e5 + 3 scale)
      // against a sampled 1e5 + 4 scale.
      FuzzyStudyResults r = one_output_results(Interval{1e5, 1e5 + 6 * scale},
                                               Interval{1e5, 1e5 + 4 * scale});
      r.proofs.upper      = {{BoundProof{1e5 + 6 * scale, 1e5 + 3 * scale}}};
      std::ostringstream out;
      nlohmann::json     entry;
      FuzzyStudyReport::comparison(r, 0, out, entry);
      ASSERT_NE(out.str().find("1 bound(s) lie beyond the Extension "
                               "Principle's interval only by the reduction "
                               "error"),
                std::string::npos)
        << out.str();
      const bool        round_off = scale < 1e-3;
      const std::string text      = out.str();
      const std::size_t at        = text.find("only by the reduction error");
      const std::string line      = text.substr(at, text.find('\n', at) - at);
      EXPECT_EQ(line.find("within its accuracy, 1.0e-07 of its magnitude "
                          "1.000e+05, so round-off") != std::string::npos,
                round_off)
        << out.str();
    }
}

// Spot checks (fuzzy/spot_checks.h): of 12 recorded evaluations of a fast
// response, 4 evenly spread ones (the middles of four equal parts: the 2nd,
// 5th, 8th and 11th) are solved by the exact response once more. The fast
// response is the exact one, y = (x0 + x1, x0 x1), plus an error on the
// second output that grows along the record (1e-3 times the evaluation's
// index), with no solution where x0 < 0 (both) and where the fast one
// alone says so at x0 = 5: the largest difference is the last checked
// point's, 1e-3 * 10, the first output has none, the point of x0 = -1 is
// without a solution on both sides and the one at x0 = 4 (fast: none)
// disagrees.
TEST(SpotChecks, ChecksEvenlySpreadEvaluationsAgainstTheExactResponse)
{
  const Response exact = [](const std::vector<double> &x) {
    if (x[0] < 0)
      return std::vector<double>();
    return std::vector<double>{x[0] + x[1], x[0] * x[1]};
  };
  unsigned int   calls = 0;
  const Response fast  = [&](const std::vector<double> &x) {
    const double error = 1e-3 * calls++;
    if (x[0] == 4)
      return std::vector<double>();
    std::vector<double> y = exact(x);
    if (!y.empty())
      y[1] += error;
    return y;
  };
  EvaluationRecord record;
  const Response   recorded = record.recording(fast);
  // x0 of the 12 evaluations: the 2nd (index 1) is -1, the 5th (4) is 4.
  const std::vector<double> x0 = {0, -1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  for (const double x : x0)
    recorded({x, 2.});
  ASSERT_EQ(record.evaluations().size(), 12u);
  EXPECT_GE(record.evaluations()[3].seconds, 0.);
  unsigned int   exact_calls = 0;
  const Response counted     = [&](const std::vector<double> &x) {
    ++exact_calls;
    return exact(x);
  };
  const SpotChecks c = spot_check(record, 4, counted, MPI_COMM_SELF);
  EXPECT_EQ(c.n_recorded, 12u);
  EXPECT_EQ(c.n_checked, 4u);
  EXPECT_EQ(exact_calls, 4u);
  EXPECT_EQ(c.n_without_solution, 1u);
  EXPECT_EQ(c.n_disagreeing, 1u);
  EXPECT_EQ(c.n_fast_without, 1u);
  ASSERT_EQ(c.disagreeing.size(), 1u);
  EXPECT_EQ(c.disagreeing[0], (std::vector<double>{4., 2.}));
  ASSERT_EQ(c.largest_difference.size(), 2u);
  EXPECT_EQ(c.largest_difference[0], 0.);
  EXPECT_NEAR(c.largest_difference[1], 1e-2, 1e-13);
  EXPECT_EQ(c.argument[1], (std::vector<double>{10., 2.}));
  EXPECT_GE(c.exact_seconds, 0.);
  // More asked than recorded: every evaluation, once.
  exact_calls = 0;
  EXPECT_EQ(spot_check(record, 100, counted, MPI_COMM_SELF).n_checked, 12u);
  EXPECT_EQ(exact_calls, 12u);
  // After clear(), nothing to check.
  record.clear();
  EXPECT_EQ(spot_check(record, 4, counted, MPI_COMM_SELF).n_checked, 0u);
}

// The report of the spot checks: an output whose largest |reduced - exact|
// exceeds the proofs' tolerance of its range is a warning line naming it
// and flagged in results.json; within it, or within the accuracy of the
// output's magnitude (round-off of a crisp output), none.
TEST(FuzzyStudyReport, SpotChecksBeyondTheToleranceAreAWarning)
{
  for (const double difference : {1e-6, 1e-3, 5e-9})
    {
      // Fn over [1e5, 1e5 + 10] at alpha 0 (range 10), tolerance 1e-4 of
      // it (1e-3), accuracy 1e-7 of the magnitude (1e-2).
      FuzzyStudyResults r =
        one_output_results(Interval{1e5, 1e5 + 10}, Interval{1e5, 1e5 + 10});
      r.proof_settings.tolerance       = 1e-4;
      r.proof_settings.accuracy        = 1e-13;
      r.proof_settings.spot_checks     = 3;
      r.proof_settings.spot_checks     = 1;
      r.spot_checks.n_recorded         = 30;
      r.spot_checks.n_checked          = 3;
      r.spot_checks.fast_seconds       = 3e-3;
      r.spot_checks.exact_seconds      = 6e-2;
      r.spot_checks.largest_difference = {difference * 10};
      r.spot_checks.argument           = {{0.25}};
      r.parameters.resize(1);
      r.parameters[0].quantity.name = "P1.E";
      Report         report;
      nlohmann::json json;
      FuzzyStudyReport::spot_checks(r, report, json);
      const std::string text   = report.text();
      const bool        beyond = difference > 1e-4;
      EXPECT_EQ(text.find("warning: spot checks: Fn: reduced - exact reaches "
                          "1.00e-02, 1.00e-03 of the output's range "
                          "(tolerance 1.0e-04), at (P1.E = 0.25)") !=
                  std::string::npos,
                beyond)
        << text;
      EXPECT_EQ(text.find("warning:") != std::string::npos, beyond) << text;
      EXPECT_EQ(json["spot_checks"]["all_within_tolerance"].get<bool>(),
                !beyond);
      EXPECT_EQ(
        json["spot_checks"]["outputs"][0]["within_tolerance"].get<bool>(),
        !beyond);
      EXPECT_NE(text.find("one evaluation at these points: 1.000 ms reduced"),
                std::string::npos)
        << text;
      EXPECT_NEAR(json["spot_checks"]["ratio"].get<double>(), 20., 1e-12);
    }
  // A crisp output: 1e-3 of its range of 1e-8 is round-off, within 1e-7 of
  // its magnitude 1e5: no warning.
  FuzzyStudyResults r =
    one_output_results(Interval{1e5, 1e5 + 1e-8}, Interval{1e5, 1e5 + 1e-8});
  r.proof_settings.tolerance       = 1e-4;
  r.proof_settings.spot_checks     = 1;
  r.spot_checks.n_checked          = 1;
  r.spot_checks.largest_difference = {1e-11};
  r.spot_checks.argument           = {{}};
  Report         report;
  nlohmann::json json;
  FuzzyStudyReport::spot_checks(r, report, json);
  EXPECT_EQ(report.text().find("warning:"), std::string::npos) << report.text();
}
