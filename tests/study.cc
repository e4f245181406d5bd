// Tests of the study layer: the binding of named scene quantities to a
// state, the models set from it, and the outputs (observations) chosen by
// name. The references are hand-computed values, independent solvers set up
// without the study layer, and the definitions of the outputs; the hard case
// is a scene with two contact pairs of different friction.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/contact/full_order_contact.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/vertex_method.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_quantity.h>
#include <fuzzycontact/scene/scene_state.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <gtest/gtest.h>

#include "test_utilities.h"
#include <cmath>
#include <fstream>
#include <sstream>

using namespace FuzzyContact;
using namespace FuzzyContact::Testing;

namespace
{
  Scene
  scene(const std::string &name)
  {
    return Scene::read(source_dir + "/prm/" + name + ".prm");
  }

  // The per-pair outputs of the three-beams scene.
  const std::vector<std::string> pair_outputs =
    {"lower.Fn", "lower.Ft", "upper.Fn", "upper.Ft", "Fn", "Ft", "slave.uy"};
} // namespace


// ----------------------------------------------------------------------------
// Scene quantities and their binding to a state
// ----------------------------------------------------------------------------

// <component>.E over zones of different moduli: the area-weighted mean,
// and setting it scales every zone; a zone quantity sets its zone alone;
// two fuzzy parameters that set the same modulus are refused.
TEST(SceneQuantity, WholeComponentOverZonesThatDiffer)
{
  Scene s = scene("cantilever-zones");
  // root [0, 0.05] and tip [0.05, 0.2] of the same height: areas 1 : 3,
  // mean (200 + 3 x 100) / 4 = 125 GPa.
  s.components[0].zones[0].x_range        = {{0, 0.05}};
  s.components[0].zones[1].x_range        = {{0.05, 0.2}};
  s.components[0].zones[0].youngs_modulus = 200e9;
  s.components[0].zones[1].youngs_modulus = 100e9;
  const SceneQuantity E                   = SceneQuantity::parse("beam.E", s);
  EXPECT_NEAR(E.value(s), 125e9, 1e-3);
  SceneState state(s);
  E.apply(state, s, 150e9);
  EXPECT_NEAR(state.zone_moduli[0][0], 240e9, 1e-3);
  EXPECT_NEAR(state.zone_moduli[0][1], 120e9, 1e-3);
  EXPECT_NEAR(E.value(state, s), 150e9, 1e-3);
  const SceneQuantity root = SceneQuantity::parse("beam.root.E", s);
  SceneState          other(s);
  root.apply(other, s, 50e9);
  EXPECT_EQ(other.zone_moduli[0], (std::vector<double>{50e9, 100e9}));
  EXPECT_TRUE(E.overlaps(root, s));
  EXPECT_FALSE(root.overlaps(SceneQuantity::parse("beam.tip.E", s), s));
  EXPECT_FALSE(root.overlaps(SceneQuantity::parse("beam.root.rho", s), s));

  const std::string message = error_of([&] {
    fuzzy_parameters(s,
                     "set fuzzy parameters = beam.E, beam.root.E\n"
                     "subsection Fuzzy parameter beam.E\n"
                     "set values = 1e11, 2e11, 3e11\nend\n"
                     "subsection Fuzzy parameter beam.root.E\n"
                     "set values = 1e11, 2e11, 3e11\nend\n");
  });
  EXPECT_NE(message.find("fuzzy parameters: <beam.E> and <beam.root.E> set "
                         "the same value of the scene"),
            std::string::npos)
    << message;
}

// The gap of a pair is its nominal gap shifted: the state holds the shift.
TEST(SceneQuantity, GapAndFrictionPerPair)
{
  const Scene         s   = scene("three-beams");
  const SceneQuantity gap = SceneQuantity::parse("upper.gap", s);
  const SceneQuantity mu  = SceneQuantity::parse("lower.mu", s);
  EXPECT_NEAR(gap.value(s), 1e-8, 1e-18);
  SceneState state(s);
  gap.apply(state, s, 3e-8);
  mu.apply(state, s, 0.2);
  EXPECT_NEAR(state.gap_offsets[1], 2e-8, 1e-18);
  EXPECT_EQ(state.gap_offsets[0], 0.);
  EXPECT_EQ(state.friction_coefficients, (std::vector<double>{0.2, 0.5}));
  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("middle.mu", s);
            })
              .find("the scene has no contact pair <middle> (its contact "
                    "pairs: lower, upper)"),
            std::string::npos);
}


// ----------------------------------------------------------------------------
// Observations
// ----------------------------------------------------------------------------

TEST(Observations, NamesAreCheckedBeforeMeshing)
{
  const Scene s = scene("three-beams");
  EXPECT_EQ(Observations::split("P1.node(0.2, 0).ux, Fn ,upper.Ft"),
            (std::vector<std::string>{"P1.node(0.2, 0).ux", "Fn", "upper.Ft"}));
  const auto refusal = [&](const std::string &list) {
    return error_of([&] {
      Observations::check(Observations::split(list), s);
    });
  };
  EXPECT_NE(refusal("Fn, Fn").find("outputs: <Fn> appears twice"),
            std::string::npos);
  EXPECT_NE(refusal("Fn,").find("contains an empty name"), std::string::npos);
  EXPECT_NE(refusal("P1.node(0.2, 0.ux").find("unbalanced parentheses"),
            std::string::npos);
  EXPECT_NE(refusal("P4.node(0.2, 0).ux")
              .find("outputs: <P4.node(0.2, 0).ux>: the scene has no "
                    "component <P4> (its components: P1, P2, P3)"),
            std::string::npos);
  EXPECT_NE(refusal("P1.node(0.5, 0).ux")
              .find("the point (0.5, 0) lies outside component P1"),
            std::string::npos);
  EXPECT_NE(refusal("P1.node(x, 0).uy").find("<x> is not a number"),
            std::string::npos);
  EXPECT_NE(refusal("middle.Fn")
              .find("the scene has no contact pair "
                    "<middle> (its contact pairs: lower, "
                    "upper)"),
            std::string::npos);
  EXPECT_NE(refusal("upper.pressure").find("not an output; use"),
            std::string::npos);
  EXPECT_NE(refusal("P1.node(0.2, 0).uz").find("not an output; use"),
            std::string::npos);
  EXPECT_EQ(refusal("P1.node(0.2, 0.008).uy, lower.max_pressure, "
                    "upper.contact_length, slave.ux, master2.uy"),
            "");
}

// The nodes: the nearest node of the component, the report node and the
// master segment under it; the values are those of the displacement fields
// at their DoFs.
TEST(Observations, NodesAndAliasesReadTheDisplacementFields)
{
  ContactScene       bodies(scene("overlap"), 0);
  const Observations outputs({"P1.node(0.2, 0.008).uy",
                              "P2.node(0.1013, -0.0001).ux",
                              "slave.ux",
                              "master1.uy"},
                             bodies);
  // P1's top-right corner; P2's nearest node to (0.1013, -0.0001): on its
  // top face, the mid-side node at x = 0.1 + 0.2 / 150.
  EXPECT_NEAR(outputs[0].position[0], 0.2, 1e-14);
  EXPECT_NEAR(outputs[0].position[1], 0.00800001, 1e-14);
  EXPECT_NEAR(outputs[1].position[0], 0.1 + 0.2 / 150, 1e-14);
  EXPECT_NEAR(outputs[1].position[1], 0., 1e-14);
  EXPECT_NEAR(outputs[2].position[0], 0.2, 1e-14);
  EXPECT_NEAR(outputs[2].position[1], 1e-8, 1e-20);
  EXPECT_EQ(outputs[0].unit(), "m");

  FullOrderModel full(bodies, outputs.dofs());
  full.set_state(SceneState(bodies.scene()));
  const ContactSolution     s = full.solve();
  const std::vector<double> v = outputs.values(s);
  ASSERT_EQ(s.displacements.size(), 2u);
  for (unsigned int i = 0; i < outputs.size(); ++i)
    EXPECT_EQ(v[i], s.displacements[outputs[i].component][outputs[i].dof]);
  // The tip deflects down, the master node under it too.
  EXPECT_LT(v[0], -1e-3);
  EXPECT_LT(v[3], -1e-3);
}

// Pair outputs against values known by hand: on `overlap` without friction
// only P1's tip corner closes (a vertex of a Q2 face: tributary length h/6,
// h = 0.2/75), so the contact length is h/6 and the largest pressure F_n /
// (h/6 t); the pairs' forces add up to the totals on `three-beams`.
TEST(Observations, PairOutputsAgreeWithHandValues)
{
  {
    ContactScene       bodies(scene("overlap"), 0);
    const Observations outputs({"interface.Fn",
                                "interface.max_pressure",
                                "interface.contact_length"},
                               bodies);
    SceneState         state(bodies.scene());
    state.friction_coefficients = {0.};
    FullOrderModel full(bodies, outputs.dofs());
    full.set_state(state);
    const ContactSolution s = full.solve();
    ASSERT_EQ(s.n_nodes() - s.count(ContactStatus::open), 1u);
    const std::vector<double> v = outputs.values(s);
    const double              h = 0.2 / 75;
    EXPECT_NEAR(v[2], h / 6, 1e-15);
    EXPECT_NEAR(v[1], v[0] / (h / 6 * 1.), 1e-9 * v[1]);
    EXPECT_EQ(v[0], s.normal_force);
  }
  {
    ContactScene       bodies(scene("three-beams"), 0);
    const Observations outputs(pair_outputs, bodies);
    FullOrderModel     full(bodies, outputs.dofs());
    full.set_state(SceneState(bodies.scene()));
    const std::vector<double> v = outputs.values(full.solve());
    EXPECT_NEAR(v[0] + v[2], v[4], 1e-12 * v[4]);
    EXPECT_NEAR(v[1] + v[3], v[5], 1e-12 * v[4]);
    EXPECT_GT(v[0], 0.);
    EXPECT_GT(v[2], 0.);
  }
}


// ----------------------------------------------------------------------------
// Two contact pairs of different friction
// ----------------------------------------------------------------------------

// three-beams: the lower pair is frictionless, the upper one has mu = 0.5.
// The full-order model, an independent full-order solve set up without the
// study layer, the exact reduced solver (1e-8) and FL2C (its tolerance,
// 1e-9 here: 1e-6) agree pair by pair; the lower pair carries no friction
// force and the upper one slips at the cone.
TEST(TwoPairs, EverySolverKeepsEachPairsFriction)
{
  ContactScene       bodies(scene("three-beams"), 0);
  const Observations outputs(pair_outputs, bodies);
  const SceneState   state(bodies.scene());

  FullOrderModel full(bodies, outputs.dofs());
  full.set_state(state);
  const std::vector<double> f = outputs.values(full.solve());

  // Independent: the interface's per-node coefficients, straight from the
  // scene.
  FullOrderContact direct(bodies.components(), bodies.interface());
  direct.observe(outputs.dofs());
  const ContactSolution d = direct.solve();

  ReducedModelSettings settings;
  ReducedOrderModel    reduced(bodies,
                            component_modes(bodies, ModalParameters()),
                            outputs.dofs(),
                            std::vector<VaryingQuantity>(),
                            settings);
  reduced.set_state(state);
  const std::vector<double> r =
    outputs.values(reduced.solve(ActiveSetSolver()));
  FL2CParameters fl2c;
  fl2c.tolerance              = 1e-9;
  const std::vector<double> g = outputs.values(reduced.solve(FL2CSolver(fl2c)));

  const std::vector<double> v = outputs.values(d);
  for (unsigned int i = 0; i < pair_outputs.size(); ++i)
    {
      const double scale = i == 6 ? std::abs(f[6]) : f[4];
      EXPECT_NEAR(v[i], f[i], 1e-12 * scale) << pair_outputs[i];
      EXPECT_NEAR(r[i], f[i], 1e-8 * scale) << pair_outputs[i];
      EXPECT_NEAR(g[i], f[i], 1e-6 * scale) << pair_outputs[i];
    }
  EXPECT_EQ(f[1], 0.);
  EXPECT_EQ(g[1], 0.);
  EXPECT_GT(std::abs(f[3]), 0.1 * f[2]);
  EXPECT_NEAR(std::abs(f[3]), 0.5 * f[2], 1e-9 * f[2]);
}

// The fuzzy study on three-beams with a fuzzy modulus of the middle beam:
// its exact reference keeps each pair's friction (it gave every node the
// first pair's mu = 0 before, and F_t = 0 where the reduced path and an
// independent solve give about 0.5 F_n of the upper pair).
TEST(TwoPairs, FuzzyStudyReferenceKeepsEachPairsFriction)
{
  const Scene             s   = scene("three-beams");
  const FuzzyParameterSet set = fuzzy_parameters(
    s,
    "set fuzzy parameters = P1.E\nsubsection Fuzzy parameter P1.E\n"
    "set values = 0.9, 1, 1.1\nset relative = true\nend\n");
  FuzzyContactModelSettings settings;
  settings.mesh_refinements = 0;
  settings.fl2c.tolerance   = 1e-10;
  FuzzyContactModel model(s, set, pair_outputs, settings);

  // Independent: the bodies with P1's modulus set by hand, solved exactly.
  ContactScene       bodies(s, 0);
  const Observations outputs(pair_outputs, bodies);
  for (const double E : {0.9 * 210e9, 210e9, 1.1 * 210e9})
    {
      SceneState state(s);
      state.zone_moduli[0] = {E};
      bodies.set_materials(state);
      FullOrderContact direct(bodies.components(), bodies.interface());
      direct.observe(outputs.dofs());
      const std::vector<double> d = outputs.values(direct.solve());
      const std::vector<double> f = model.full_order({E});
      const std::vector<double> r = model.reduced({E});
      for (unsigned int i = 0; i < pair_outputs.size(); ++i)
        {
          const double scale = i == 6 ? std::abs(d[6]) : d[4];
          EXPECT_NEAR(f[i], d[i], 1e-9 * scale) << pair_outputs[i];
          EXPECT_NEAR(r[i], d[i], 1e-7 * scale) << pair_outputs[i];
        }
      EXPECT_GT(std::abs(f[3]), 0.1 * f[2]);
    }
}

// step-4's key `contact solver` (FuzzyContactModelSettings): the reduced
// model solved by FL2C (the default) or by the exact reduced solver, said
// in the model's description. On `stacked` (distributed contact) with a
// fuzzy friction coefficient from 0 to 0.6 and a fuzzy load, both give the
// same bounds (vertex method, 3 levels) within 1e-6 of each output's
// largest magnitude: FL2C converges to the exact reduced solution.
TEST(FuzzyContactModel, ContactSolverChoiceGivesTheSameBounds)
{
  const Scene             s   = scene("stacked");
  const FuzzyParameterSet set = fuzzy_parameters(
    s,
    "set fuzzy parameters = interface.mu, P1.tip.force\n"
    "subsection Fuzzy parameter interface.mu\nset values = 0, 0.3, 0.6\nend\n"
    "subsection Fuzzy parameter P1.tip.force\n"
    "set values = 10e3, 50e3, 100e3\nend\n");
  const std::vector<std::string> outputs = {"slave.ux", "slave.uy", "Fn", "Ft"};
  std::vector<FuzzyOutputBounds> bounds;
  for (const std::string solver : {"fl2c", "reduced exact"})
    {
      ParameterHandler prm;
      FuzzyContactModelSettings::declare_parameters(prm);
      prm.parse_input_from_string("set mesh refinements = 0\n"
                                  "set contact solver = " +
                                  solver + "\n");
      FuzzyContactModelSettings settings;
      settings.parse_parameters(prm);
      EXPECT_EQ(settings.contact_solver, solver);
      FuzzyContactModel model(s, set, outputs, settings);
      EXPECT_EQ(model.contact_solver(), solver);
      EXPECT_NE(model.describe().find(solver == "fl2c"
                                        ? "solved by FL2C (fuzzy regulators"
                                        : "solved by the exact reduced solver "
                                          "(reduced exact"),
                std::string::npos)
        << model.describe();
      bounds.push_back(VertexMethod().bounds(
        set.numbers(),
        alpha_levels(3),
        [&](const std::vector<double> &p) {
          return model.reduced(p);
        },
        outputs,
        MPI_COMM_SELF));
    }
  for (unsigned int k = 0; k < outputs.size(); ++k)
    {
      double scale = 0;
      for (const Interval &i : bounds[1].bounds[k])
        scale = std::max({scale, std::abs(i.lower), std::abs(i.upper)});
      EXPECT_GT(scale, 0) << outputs[k];
      EXPECT_LE(max_relative_difference(bounds[0].bounds[k],
                                        bounds[1].bounds[k],
                                        scale),
                1e-6)
        << outputs[k];
    }
  // An unknown solver name is refused by the key's pattern.
  ParameterHandler prm;
  FuzzyContactModelSettings::declare_parameters(prm);
  EXPECT_ANY_THROW(
    prm.parse_input_from_string("set contact solver = newton\n"));
}


// A reduced model built without the reanalysis of a component cannot
// represent a change of one of its zones, and says so.
TEST(ReducedOrderModel, RefusesAStateItWasNotBuiltFor)
{
  Scene s                       = scene("overlap");
  s.components[0].implicit_zone = false;
  s.components[0].zones         = {
            MaterialZone{"root", {{0, 0.08}}, {{-1, 1}}, 210e9, 0.3, 7900},
            MaterialZone{"rest", {{0.08, 0.2}}, {{-1, 1}}, 210e9, 0.3, 7900}};
  ContactScene       bodies(s, 0);
  const Observations outputs({"Fn"}, bodies);
  ReducedOrderModel  reduced(bodies,
                            component_modes(bodies, ModalParameters()),
                            outputs.dofs(),
                            std::vector<VaryingQuantity>(),
                            ReducedModelSettings());
  SceneState         state(s);
  // Both zones by one factor: exact scaling, accepted.
  state.zone_moduli[0] = {1.1 * 210e9, 1.1 * 210e9};
  reduced.set_state(state);
  state.zone_moduli[0] = {1.1 * 210e9, 210e9};
  EXPECT_NE(error_of([&] {
              reduced.set_state(state);
            }).find("The reduced model of component P1 has no reanalysis"),
            std::string::npos);
}


// ----------------------------------------------------------------------------
// Bodies held by contact alone
// ----------------------------------------------------------------------------

namespace
{
  // The outputs of @p scene solved by the full-order model, the exact
  // reduced solver and FL2C on modes + static correction (mesh as read).
  std::vector<std::vector<double>>
  three_ways(const Scene &s, const std::vector<std::string> &names)
  {
    ContactScene       bodies(s, 0);
    const Observations outputs(names, bodies);
    const SceneState   state(s);
    FullOrderModel     full(bodies, outputs.dofs());
    full.set_state(state);
    ReducedOrderModel reduced(bodies,
                              component_modes(bodies, ModalParameters()),
                              outputs.dofs(),
                              std::vector<VaryingQuantity>(),
                              ReducedModelSettings());
    reduced.set_state(state);
    FL2CParameters fl2c;
    fl2c.tolerance = 1e-10;
    return {outputs.values(full.solve()),
            outputs.values(reduced.solve(ActiveSetSolver())),
            outputs.values(reduced.solve(FL2CSolver(fl2c)))};
  }

  // @p text with the block's friction coefficient set to @p mu.
  Scene
  slope_with_friction(const double mu)
  {
    std::ifstream      in(source_dir + "/prm/slope.prm");
    std::ostringstream text;
    text << in.rdbuf();
    Scene s = Scene::read_from_string(replace(text.str(),
                                              "set friction coefficient = 0.5",
                                              "set friction coefficient = " +
                                                std::to_string(mu)),
                                      source_dir + "/prm/slope.prm");
    return s;
  }
} // namespace

// A block on a 20-degree slope, pressed by a vertical force F on its top
// face, held by nothing but its contact (prm/slope.prm: its three
// rigid-body motions are unknowns). Statics: it stays put if mu >= tan(20
// deg) = 0.364, and then the contact forces are N = F cos(20 deg) and T = F
// sin(20 deg) whatever the pressure distribution (every model, to
// round-off); with less friction there is no static solution, which every
// model says before it tries.
TEST(FloatingBodies, BlockOnASlopeAgainstStatics)
{
  const double theta = 20 * M_PI / 180, F = 1e4;
  for (const double mu : {0.5, 1.02 * std::tan(theta)})
    {
      const auto v = three_ways(slope_with_friction(mu),
                                {"Fn", "Ft", "Block.node(0.2, 0.15).uy"});
      for (const auto &w : v)
        {
          EXPECT_NEAR(w[0], F * std::cos(theta), 1e-10 * F) << "mu = " << mu;
          EXPECT_NEAR(std::abs(w[1]), F * std::sin(theta), 1e-10 * F)
            << "mu = " << mu;
          EXPECT_NEAR(w[2], v[0][2], 1e-8 * std::abs(v[0][2]));
        }
    }
  // The moment: the contact forces on the block (p_n n + p_t tau at each
  // slave node, n and tau the slope's) balance the load's, F (0, -1) at the
  // middle of the block's top face, about the origin.
  const Scene    s = slope_with_friction(0.5);
  ContactScene   bodies(s, 0);
  FullOrderModel full(bodies, ObservedDofs(2));
  full.set_state(SceneState(s));
  const ContactSolution solution = full.solve();
  double                moment   = 0;
  for (unsigned int k = 0; k < solution.n_nodes(); ++k)
    {
      const ContactNode &node = bodies.interface().nodes()[k];
      const Tensor<1, 2> f =
        solution.p_n(k) * node.normal + solution.p_t(k) * node.tangent;
      moment += node.slave.position[0] * f[1] - node.slave.position[1] * f[0];
    }
  const double   c = std::cos(theta), sn = std::sin(theta);
  const Point<2> corner(0.15, 0.05 + 0.15 * std::tan(theta));
  const Point<2> top =
    corner + Point<2>(0.05 * c - 0.05 * sn, 0.05 * sn + 0.05 * c);
  moment += top[0] * (-F);
  EXPECT_NEAR(moment, 0., 1e-10 * F * 0.4);
  EXPECT_GT(solution.count(ContactStatus::stick), 0u);
  for (const double mu : {0.3, 0.98 * std::tan(theta)})
    {
      const std::string m = error_of([&] {
        three_ways(slope_with_friction(mu), {"Fn"});
      });
      EXPECT_NE(m.find("no static equilibrium"), std::string::npos)
        << "mu = " << mu << ": " << m;
      EXPECT_NE(m.find("Block: rotation about"), std::string::npos) << m;
      // The friction it needs is statics' tan(theta).
      const auto needed = m.find(", would be ");
      ASSERT_NE(needed, std::string::npos) << m;
      EXPECT_NEAR(std::atof(m.c_str() + needed + 11),
                  std::tan(theta),
                  1e-6 * std::tan(theta))
        << m;
    }
}

// The contact patch test (prm/patch-test.prm, matching meshes) with the
// upper block pressed by a pressure p on its top instead of a prescribed
// displacement: held in x by its symmetry line only, it floats vertically.
// The exact solution is the uniform uniaxial stress sigma_yy = -p
// (plane strain): the contact force p w t, the interface's u_y = -p H_2 /
// E', the top's u_y = -p (H_1 + H_2) / E' (E' = E / (1 - nu^2)) and the
// lateral expansion u_x = nu (1 + nu) p x / E at the top right corner.
TEST(FloatingBodies, PatchTestUnderAPressure)
{
  std::ifstream      in(source_dir + "/prm/patch-test.prm");
  std::ostringstream text;
  text << in.rdbuf();
  std::string t  = replace(text.str(),
                          "subdivisions       = 7, 3",
                          "subdivisions       = 5, 3");
  t              = replace(t,
              "  set supports           = press, symmetry\n"
                           "  subsection Support press\n"
                           "    set face             = top\n"
                           "    set fixed components = y\n"
                           "    set displacement     = 0, -1e-5\n"
                           "  end\n",
              "  set supports           = symmetry\n"
                           "  set loads              = press\n"
                           "  subsection Load press\n"
                           "    set face     = top\n"
                           "    set pressure = 2e7\n"
                           "  end\n");
  const Scene  s = Scene::read_from_string(t, source_dir + "/prm/patch.prm");
  const double p = 2e7, E = 210e9, nu = 0.3, H = 0.05, w = 0.1;
  const double Ep = E / (1 - nu * nu);
  for (const auto &v : three_ways(s,
                                  {"Fn",
                                   "Lower.node(0.1, 0.05).uy",
                                   "Upper.node(0.1, 0.1).uy",
                                   "Upper.node(0.1, 0.1).ux"}))
    {
      EXPECT_NEAR(v[0], p * w, 1e-10 * p * w);
      EXPECT_NEAR(v[1], -p * H / Ep, 1e-9 * p * H / Ep);
      EXPECT_NEAR(v[2], -2 * p * H / Ep, 1e-9 * p * H / Ep);
      EXPECT_NEAR(v[3], nu * (1 + nu) * p * w / E, 1e-9 * p * H / Ep);
    }
}

// The roller of prm/hertz-load.prm with a little friction (mu = 0.03):
// held by its contact vertically and against rotation, it turns in answer
// to the friction forces of all slipping nodes at once, which kept the
// primal-dual iterations from settling (they rocked from all nodes slipping
// one way to all slipping the other); the exact solvers then ramp the
// friction coefficients up from 0. Every model must find the same, nearly
// symmetric answer: the applied force carried, and a net friction force
// far below mu P (the meshes are not symmetric: 4.5e-7 P).
TEST(FloatingBodies, RollerWithLittleFriction)
{
  std::ifstream      in(source_dir + "/prm/hertz-load.prm");
  std::ostringstream text;
  text << in.rdbuf();
  const Scene s =
    Scene::read_from_string(replace(text.str(),
                                    "set friction coefficient = 0\n",
                                    "set friction coefficient = 0.03\n"),
                            source_dir + "/prm/hertz-load.prm");
  const double P = s.components[0].loads[0].total_force;
  const auto   v = three_ways(s, {"Fn", "Ft"});
  for (const auto &w : v)
    {
      EXPECT_NEAR(w[0], P, 1e-10 * P);
      EXPECT_NEAR(w[1], 0., 1e-5 * P);
      EXPECT_NEAR(w[1], v[0][1], 1e-10 * P);
    }
}
