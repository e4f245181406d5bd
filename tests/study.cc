// Tests of the study layer: the binding of named scene quantities to a
// state, the models set from it, and the outputs (observations) chosen by
// name. The references are hand-computed values, independent solvers set up
// without the study layer, and the definitions of the outputs; the hard case
// is a scene with two contact pairs of different friction.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_workspace.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/contact/full_order_contact.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/fe/stress_state.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/vertex_method.h>
#include <fuzzycontact/output/contact_face_plot.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/output/stress_postprocessor.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_quantity.h>
#include <fuzzycontact/scene/scene_state.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>
#include <fuzzycontact/study/sliding_probes.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include "gauss_point_stresses.h"
#include "test_utilities.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
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
  // Reports give a node to the mesh's precision (1e-9 of its body's size,
  // at most 10 digits): a coordinate at round-off of zero is 0.
  EXPECT_EQ(outputs[0].description(), "u_y of P1's node (0.2, 0.00800001)");
  EXPECT_EQ(outputs[1].description(), "u_x of P2's node (0.1013333333, 0)");
  Observation on_axis = outputs[1];
  on_axis.position    = Point<2>(2.45812e-14, 0.12);
  EXPECT_EQ(on_axis.description(), "u_x of P2's node (0, 0.12)");

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

    // With friction the same corner carries F_t: its shear traction is
    // |F_t| / (h/6 t).
    const Observations sheared({"interface.Ft", "interface.max_shear"}, bodies);
    state.friction_coefficients = {0.3};
    full.set_state(state);
    const ContactSolution f = full.solve();
    ASSERT_EQ(f.n_nodes() - f.count(ContactStatus::open), 1u);
    const std::vector<double> w = sheared.values(f);
    EXPECT_GT(std::abs(w[0]), 1e-3 * f.normal_force);
    EXPECT_NEAR(w[1], std::abs(w[0]) / (h / 6 * 1.), 1e-9 * w[1]);
    EXPECT_EQ(sheared[1].unit(), "Pa");
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
    // The frictionless lower pair has no shear traction; the upper one has.
    const Observations shear({"lower.max_shear", "upper.max_shear"}, bodies);
    FullOrderModel     again(bodies, shear.dofs());
    again.set_state(SceneState(bodies.scene()));
    const std::vector<double> t = shear.values(again.solve());
    EXPECT_EQ(t[0], 0.);
    EXPECT_GT(t[1], 0.);
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

namespace
{
  // The fuzzy modulus of three-beams' middle beam P1 (+-10 %).
  FuzzyParameterSet
  p1_modulus(const Scene &s)
  {
    return fuzzy_parameters(
      s,
      "set fuzzy parameters = P1.E\nsubsection Fuzzy parameter P1.E\n"
      "set values = 0.9, 1, 1.1\nset relative = true\nend\n");
  }
} // namespace

// The fuzzy study on three-beams with a fuzzy modulus of the middle beam:
// its exact reference keeps each pair's friction (it gave every node the
// first pair's mu = 0 before, and F_t = 0 where the reduced path and an
// independent solve give about 0.5 F_n of the upper pair).
TEST(TwoPairs, FuzzyStudyReferenceKeepsEachPairsFriction)
{
  const Scene               s   = scene("three-beams");
  const FuzzyParameterSet   set = p1_modulus(s);
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

// step-4's `Exact contact solver` keys reach its exact full-order
// reference too (the Extension Principle's samples, the proofs): it solved
// with the defaults whatever the step file said, while its "did not
// converge" message named the key. With `max iterations = 1` the three
// beams' reference stops there and says so; with the default it answers.
TEST(TwoPairs, TheExactSolverKeysReachTheFullOrderReference)
{
  const Scene               s   = scene("three-beams");
  const FuzzyParameterSet   set = p1_modulus(s);
  FuzzyContactModelSettings settings;
  settings.mesh_refinements     = 0;
  settings.contact_solver       = "reduced exact";
  settings.exact.max_iterations = 1;
  FuzzyContactModel limited(s, set, pair_outputs, settings);
  std::string       message;
  try
    {
      limited.full_order({210e9});
    }
  catch (const ExceptionBase &e)
    {
      message = Input::message_of(e);
    }
  EXPECT_NE(message.find("did not converge in 1 iterations"), std::string::npos)
    << message;
  EXPECT_NE(message.find("Exact contact solver/max iterations"),
            std::string::npos)
    << message;
  settings.exact.max_iterations = 200;
  FuzzyContactModel enough(s, set, pair_outputs, settings);
  EXPECT_EQ(enough.full_order({210e9}).size(), pair_outputs.size());
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
  // reduced solver and (if @p fl2c_too) FL2C on modes + static correction
  // (mesh as read).
  std::vector<std::vector<double>>
  three_ways(const Scene                    &s,
             const std::vector<std::string> &names,
             const bool                      fl2c_too = true)
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
    if (!fl2c_too)
      return {outputs.values(full.solve()),
              outputs.values(reduced.solve(ActiveSetSolver()))};
    FL2CParameters fl2c;
    fl2c.tolerance = 1e-10;
    return {outputs.values(full.solve()),
            outputs.values(reduced.solve(ActiveSetSolver())),
            outputs.values(reduced.solve(FL2CSolver(fl2c)))};
  }

  // The scene prm/@p name.prm with @p from replaced by @p to.
  Scene
  edited_scene(const std::string &name,
               const std::string &from,
               const std::string &to)
  {
    const std::string  file = source_dir + "/prm/" + name + ".prm";
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return Scene::read_from_string(replace(text.str(), from, to), file);
  }

  // @p text with the block's friction coefficient set to @p mu.
  Scene
  slope_with_friction(const double mu)
  {
    return edited_scene("slope",
                        "set friction coefficient = 0.5",
                        "set friction coefficient = " + std::to_string(mu));
  }

  // A refusal for want of static equilibrium whose message gives the
  // friction coefficient the bodies need, expected to be @p needed.
  void
  expect_needs_friction(const std::string &m, const double needed)
  {
    EXPECT_NE(m.find("no static equilibrium"), std::string::npos) << m;
    const auto at = m.find(", would be ");
    ASSERT_NE(at, std::string::npos) << m;
    EXPECT_NEAR(std::atof(m.c_str() + at + 11), needed, 1e-6 * needed) << m;
  }

  // prm/bearing.prm (a column on a plate on a pedestal, both held by
  // contact alone); with @p plate_mu, pushed until the plate nearly slides:
  // 40 kN on 200 kN (the plate needs mu = 0.2), the plate's friction
  // coefficient @p plate_mu, the column's 0.7, the bed at half its modulus.
  Scene
  bearing(const std::string &plate_mu = "")
  {
    std::ifstream      in(source_dir + "/prm/bearing.prm");
    std::ostringstream text;
    text << in.rdbuf();
    std::string t = text.str();
    if (!plate_mu.empty())
      for (const auto &[from, to] :
           std::vector<std::pair<std::string, std::string>>{
             {"set friction coefficient = 0.4",
              "set friction coefficient = " + plate_mu},
             {"set friction coefficient = 0.5",
              "set friction coefficient = 0.7"},
             {"set total force = 2e4", "set total force = 4e4"},
             {"set E = 15e9", "set E = 7.5e9"}})
        t = replace(t, from, to);
    return Scene::read_from_string(t, source_dir + "/prm/bearing.prm");
  }

  // The bearing with sliding possible inside the fuzzy ranges, as
  // prm/step-4-bearing-sliding.prm makes it: the bed's modulus (+-50 %),
  // the plate's mu 0.1 .. 0.3, the column's 0.3 .. 0.7, the push 10 .. 40
  // kN.
  FuzzyParameterSet
  bearing_sliding_parameters(const Scene &s)
  {
    return fuzzy_parameters(
      s,
      "set fuzzy parameters = Pedestal.bed.E, plate-on-pedestal.mu, "
      "column-on-plate.mu, Column.push.force\n"
      "subsection Fuzzy parameter Pedestal.bed.E\nset values = 0.5, 1, 1.5\n"
      "set relative = true\nend\n"
      "subsection Fuzzy parameter plate-on-pedestal.mu\n"
      "set values = 0.1, 0.2, 0.3\nend\n"
      "subsection Fuzzy parameter column-on-plate.mu\n"
      "set values = 0.3, 0.5, 0.7\nend\n"
      "subsection Fuzzy parameter Column.push.force\n"
      "set values = 10e3, 20e3, 40e3\nend\n");
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
      EXPECT_NE(m.find("Block: rotation about"), std::string::npos) << m;
      // The friction it needs is statics' tan(theta).
      expect_needs_friction(m, std::tan(theta));
    }
}

// The shoe of prm/shoe.prm, held by contact alone, pressed (60 kN/m),
// pushed east (8 kN/m) and pushed back west (16 kN/m) in three load
// stages of 2, 3 and 3 steps: at the end the contact forces balance the
// loads (statics: F_n = 60 kN/m, F_t = +8 kN/m, the pair's sign for a net
// push of 8 kN/m west, whatever the friction did on the way), and the
// exact reduced solver agrees with the full-order one at the shoe's
// crown, after the load reversal.
TEST(FloatingBodies, AShoePushedAndPushedBackAgainstStatics)
{
  const Scene s = Scene::read(source_dir + "/prm/shoe.prm");
  const auto  v = three_ways(s,
                            {"shoe-on-plate.Fn",
                              "shoe-on-plate.Ft",
                              "Shoe.node(0.06, 0.042).ux",
                              "Shoe.node(0.06, 0.042).uy"},
                            false);
  for (const auto &w : v)
    {
      EXPECT_NEAR(w[0], 6e4, 1e-10 * 6e4);
      EXPECT_NEAR(w[1], 8e3, 1e-10 * 6e4);
      for (const unsigned int i : {2u, 3u})
        EXPECT_NEAR(w[i], v[0][i], 1e-8 * std::abs(v[0][i]));
    }
  // The push back moved the crown west of where the press left it (u_x <
  // 0 at the end), and the press moved it down.
  EXPECT_LT(v[0][2], 0.);
  EXPECT_LT(v[0][3], 0.);
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
  const Scene  s = edited_scene("hertz-load",
                               "set friction coefficient = 0\n",
                               "set friction coefficient = 0.03\n");
  const double P = s.components[0].loads[0].total_force;
  const auto   v = three_ways(s, {"Fn", "Ft"});
  for (const auto &w : v)
    {
      EXPECT_NEAR(w[0], P, 1e-10 * P);
      EXPECT_NEAR(w[1], 0., 1e-5 * P);
      EXPECT_NEAR(w[1], v[0][1], 1e-10 * P);
    }
}


// Two bodies held by contact alone, one on the other (prm/bearing.prm: a
// column on a plate on a pedestal), pushed sideways until the plate needs
// all but a little of its friction (40 kN on 200 kN: mu = 0.2 at the
// limit): nearly every node of the plate slips, and a slip that reverses
// is a small change of the free motions.
// - All but 1.1 % (mu = 0.202173): with every slipping node sticking
//   before it reverses, the iterations went from a whole interface
//   slipping to a whole interface sticking and back, and cycled to the
//   iteration limit (found by a fuzzy study of the scene); slips allowed to
//   reverse at once converge.
// - All but 0.05 % (mu = 0.2001): that fails too; a path of friction
//   coefficients from about twice what the bodies need down to the given
//   ones, the distance to the limit halved per solve, converges.
// Both exact solvers (full order, reduced) and FL2C (whose coarse
// correction is the reduced exact solver: it failed at 0.202173 before
// the path) must find the equilibrium that statics gives: each pair carries
// the press and the push.
TEST(FloatingBodies, TwoStackedBodiesNearTheLimitOfSliding)
{
  for (const std::string mu : {"0.202173", "0.2001"})
    {
      const Scene  s     = bearing(mu);
      const double press = 2e5, push = 4e4;
      const auto   v = three_ways(s,
                                {"plate-on-pedestal.Fn",
                                   "plate-on-pedestal.Ft",
                                   "column-on-plate.Fn",
                                   "column-on-plate.Ft",
                                   "Column.node(0.2, 0.13).ux"});
      ASSERT_EQ(v.size(), 3u);
      for (const auto &w : v)
        {
          ASSERT_EQ(w.size(), 5u) << "mu = " << mu;
          EXPECT_NEAR(w[0], press, 1e-9 * press) << "mu = " << mu;
          EXPECT_NEAR(std::abs(w[1]), push, 1e-9 * press) << "mu = " << mu;
          EXPECT_NEAR(w[2], press, 1e-9 * press) << "mu = " << mu;
          EXPECT_NEAR(std::abs(w[3]), push, 1e-9 * press) << "mu = " << mu;
          EXPECT_NEAR(w[4], v[0][4], 1e-8 * std::abs(v[0][4])) << "mu = " << mu;
        }
    }
}

// The key `Exact contact solver/max path solves` bounds that path: on the
// same scene at mu = 0.2001 (which needs 12 solves on it, one per halving
// of the distance to the limit), a limit of 3 makes the full-order solve
// fail at once, the path not taken, with a message that gives the solves
// it needs and the limit, and the key refuses a limit below 1 naming
// itself. Without the last resorts (ActiveSetParameters::last_resorts) the
// path is not taken. `max path failures` bounds the path's failed solves:
// on the pin of prm/pin.prm a little below the friction that holds it
// within small sliding, the path's first solve converges and each later one
// cycles (its retries, closer and closer to the first, took 32 solves, 16
// of them failed, before the key); with the default 4 the solve ends at the
// fifth failure, and with 0 at the first.
TEST(FloatingBodies, ThePathOfFrictionCoefficientsHasAKey)
{
  const Scene         s = bearing("0.2001");
  ContactScene        bodies(s, 0);
  const Observations  outputs({"plate-on-pedestal.Ft"}, bodies);
  ActiveSetParameters limited;
  limited.max_path_solves = 3;
  FullOrderModel full(bodies, outputs.dofs(), limited);
  full.set_state(SceneState(s));
  std::string message = error_of([&]() {
    full.solve();
  });
  EXPECT_NE(message.find("not along a path of friction coefficients down to "
                         "the given ones: so near the limit of sliding it "
                         "would take at least 12 solves, more than the 3 of "
                         "key 'Exact contact solver/max path solves'"),
            std::string::npos)
    << message;

  // The pin at a point of a fuzzy study of it (Lug.E 251.121 GPa, mu
  // 0.098796, 180.699 kN): the path's first solve converges, each later
  // one cycles.
  {
    const Scene  pin_scene = scene("pin");
    ContactScene pin_bodies(pin_scene, 0);
    SceneState   state(pin_scene);
    state.zone_moduli[1][0]     = 251.121e9;
    state.friction_coefficients = {0.098796};
    state.load_forces[0][0]     = 180.699e3;
    for (const auto &[failures, said] :
         std::vector<std::pair<unsigned int, std::string>>{
           {4,
            "6 solve(s) of at most 32 (key 'Exact contact solver/max "
            "path solves'), 5 failed (at most 4 may: key 'Exact contact "
            "solver/max path failures')"},
           {0,
            "2 solve(s) of at most 32 (key 'Exact contact solver/max "
            "path solves'), 1 failed (at most 0 may"},
           {10000, "32 solve(s) of at most 32"}})
      {
        ActiveSetParameters parameters;
        parameters.max_path_failures = failures;
        FullOrderModel pin(pin_bodies, ObservedDofs(2), parameters);
        pin.set_state(state);
        message = error_of([&]() {
          pin.solve();
        });
        EXPECT_NE(message.find(said), std::string::npos) << message;
      }
  }

  // Without the last resorts (as a fuzzy study's probes of a failed point
  // solve) the solve stops after the load path's attempt: it fails where
  // the path answers (TwoStackedBodiesNearTheLimitOfSliding), with the
  // attempt's own message.
  ActiveSetParameters quick;
  quick.last_resorts = false;
  FullOrderModel probe(bodies, outputs.dofs(), quick);
  probe.set_state(SceneState(s));
  message = error_of([&]() {
    probe.solve();
  });
  EXPECT_FALSE(message.empty());
  EXPECT_EQ(message.find("path of friction"), std::string::npos) << message;

  // Each key refuses a value out of its range, naming itself.
  for (const auto &[line, said] :
       std::vector<std::pair<std::string, std::string>>{
         {"set max path solves = 0",
          "max path solves must lie between 1 and 10000, got 0"},
         {"set max path failures = -1",
          "max path failures must lie between 0 and 10000, got -1"}})
    {
      ParameterHandler prm;
      ActiveSetParameters::declare_parameters(prm);
      prm.parse_input_from_string("subsection Exact contact solver\n" + line +
                                  "\nend\n");
      ActiveSetParameters parsed;
      message = error_of([&]() {
        parsed.parse_parameters(prm);
      });
      EXPECT_NE(message.find(said), std::string::npos) << message;
    }
}

// The same scene with sliding possible inside the fuzzy ranges (mu of the
// plate 0.1 .. 0.3, the push 10 .. 40 kN) and the bed's modulus fuzzy, as
// a fuzzy study evaluates it: 200 random points one after the other, each
// warm-started from its nearest evaluated point. At the 193rd (mu = 0.14,
// 12 kN: far from sliding) the start from its neighbour's statuses ended at
// the iteration limit where the start from the load path converges; the
// study stopped there. Every point must give an answer, and where the
// bodies hold, statics: each pair carries the press and the push. (The
// sequence is what made the start fail; another warm-start rule may pass
// it without the retry, and this test then proves less.)
TEST(FloatingBodies, AFailedWarmStartGivesWayToTheLoadPath)
{
  const Scene               s   = bearing();
  const FuzzyParameterSet   set = bearing_sliding_parameters(s);
  FuzzyContactModelSettings settings;
  settings.mesh_refinements = 0;
  settings.contact_solver   = "reduced exact";
  FuzzyContactModel                      model(s,
                          set,
                          {"plate-on-pedestal.Fn",
                                                "plate-on-pedestal.Ft",
                                                "column-on-plate.Ft"},
                          settings);
  const auto                             numbers = model.effective_numbers();
  std::mt19937                           random(1);
  std::uniform_real_distribution<double> unit(0, 1);
  unsigned int                           held = 0;
  for (unsigned int i = 0; i < 200; ++i)
    {
      std::vector<double> p(numbers.size());
      for (unsigned int j = 0; j < p.size(); ++j)
        {
          const auto cut = numbers[j].alpha_cut(0.);
          p[j]           = cut.lower + unit(random) * (cut.upper - cut.lower);
        }
      const std::vector<double> v = model.reduced(p);
      if (v.empty())
        continue; // no static equilibrium: the push needs more friction
      ++held;
      EXPECT_NEAR(v[0], 2e5, 1e-9 * 2e5) << "point " << i;
      EXPECT_NEAR(std::abs(v[1]), p[3], 1e-9 * 2e5) << "point " << i;
      EXPECT_NEAR(std::abs(v[2]), p[3], 1e-9 * 2e5) << "point " << i;
    }
  EXPECT_GT(held, 100u);
}

// The same study at a point where both exact solvers still fail (plate mu
// = 0.2018, 0.9 % above the 0.2 the push of 40 kN on 200 kN needs; the bed
// at half its modulus, the column's mu 0.7: doc/contact.md, section 1).
// Such a point is left out as if without equilibrium, counted, and the
// study goes on; a point 1.2 % from the limit still answers with statics,
// and a solve that fails far from the limit (here at an iteration limit of
// 2) is still an error. (The first point is chosen because the solvers
// fail there today; when they no longer do, it proves nothing: the test
// then says so.)
TEST(FloatingBodies, AFailureNearTheLimitOfSlidingLeavesThePointOut)
{
  const Scene                    s       = bearing();
  const FuzzyParameterSet        set     = bearing_sliding_parameters(s);
  const std::vector<std::string> outputs = {"plate-on-pedestal.Fn",
                                            "plate-on-pedestal.Ft"};
  FuzzyContactModelSettings      settings;
  settings.mesh_refinements = 0;
  settings.contact_solver   = "reduced exact";
  FuzzyContactModel model(s, set, outputs, settings);

  const std::vector<double> failing = {7.5e9, 0.2018, 0.7, 40e3};
  EXPECT_TRUE(model.reduced(failing).empty())
    << "the reduced exact solver now converges here: choose another point";
  EXPECT_TRUE(model.full_order(failing).empty())
    << "the full-order solver now converges here: choose another point";
  EXPECT_EQ(model.unanswered().unsolved_near_limit, 2u);
  EXPECT_EQ(model.unanswered().at_limit, 0u);

  for (const bool full : {false, true})
    {
      const std::vector<double> p = {7.5e9, 0.2025, 0.7, 40e3};
      const std::vector<double> v =
        full ? model.full_order(p) : model.reduced(p);
      ASSERT_EQ(v.size(), 2u);
      EXPECT_NEAR(v[0], 2e5, 1e-9 * 2e5);
      EXPECT_NEAR(std::abs(v[1]), 4e4, 1e-9 * 2e5);
    }
  EXPECT_EQ(model.unanswered().unsolved_near_limit, 2u);

  settings.exact.max_iterations = 2;
  FuzzyContactModel         strict(s, set, outputs, settings);
  const std::vector<double> far = {15e9, 0.3, 0.5, 10e3};
  EXPECT_THROW(strict.reduced(far), ExceptionBase);
  EXPECT_THROW(strict.full_order(far), ExceptionBase);
  EXPECT_EQ(strict.unanswered().unsolved_near_limit, 0u);
}

// The contact patch test (prm/patch-test.prm: two steel blocks, non-matching
// meshes, a symmetry line x = 0 held on both blocks, the top pressed 1e-5
// m) with friction mu = 0.3. The slave node on the symmetry line cannot
// move tangentially on either body (W_tt = 0 there): its tangential force
// is a support reaction, and the solvers stopped at it before. Exact
// answer: the uniform uniaxial stress of the frictionless test (equal
// materials, no relative lateral expansion), sigma_yy = E' eps with eps =
// 1e-5 / 0.1 and E' = E / (1 - nu^2) (plane strain, free lateral faces),
// F_n = sigma_yy 0.1 m; the friction changes it only by the non-matching
// meshes' error.
TEST(FloatingBodies, FrictionOnASymmetryLineHeldOnBothBodies)
{
  const Scene  s = edited_scene("patch-test",
                               "set friction coefficient = 0",
                               "set friction coefficient = 0.3");
  ContactScene bodies(s, 1);
  unsigned int held = 0;
  for (unsigned int k = 0; k < bodies.interface().n_nodes(); ++k)
    if (bodies.interface().friction_coefficients()[k] == 0)
      {
        ++held;
        EXPECT_NEAR(bodies.interface().node(k).slave.position[0], 0., 1e-12);
      }
  EXPECT_EQ(held, 1u);
  const double F_n = 210e9 / (1 - 0.3 * 0.3) * 1e-5 / 0.1 * 0.1;
  const auto   v   = three_ways(s, {"Fn", "Ft"});
  for (const auto &w : v)
    {
      EXPECT_NEAR(w[0], F_n, 1e-3 * F_n);
      EXPECT_LT(std::abs(w[1]), 1e-3 * F_n);
      EXPECT_NEAR(w[0], v[0][0], 1e-9 * F_n);
    }
}

// Small sliding on a flat face (contact/small_sliding.h): a steel block
// pressed 1 mm into a 50 mm rubber pad (prm/patch-test.prm with the lower
// block at E_p = 5 MPa, nu_p = 0.49, matching meshes of 60 faces across),
// frictionless on a frictionless base. Exact: a uniform uniaxial stress
// sigma in both blocks (plane strain, E' = E / (1 - nu^2)), 1e-3 = sigma H
// (1 / E'_s + 1 / E'_p), F_n = sigma w, and the pad's top edge slides out
// under the steel by the difference of their lateral strains, (nu_p (1 +
// nu_p) / E_p - nu_s (1 + nu_s) / E_s) sigma w = 1.9 mm: more than a master
// face (1.67 mm). The pad's top is flat, its normal does not turn along
// the slide: the answer is within small sliding, in all three models (a
// measure in face lengths refused it). With the pad as the slave, its edge
// slides 1.9 mm off the steel's face, and the answer is refused.
TEST(FloatingBodies, ARubberPadSlidesAlongAFlatFaceWithinSmallSliding)
{
  std::ifstream      in(source_dir + "/prm/patch-test.prm");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string lower = "subsection Component Lower";
  std::string       t     = text.str();
  const std::size_t at    = t.find(lower);
  ASSERT_NE(at, std::string::npos);
  t =
    t.substr(0, at) + replace(replace(replace(t.substr(at),
                                              "set E                  = 210e9",
                                              "set E                  = 5e6"),
                                      "set nu                 = 0.3",
                                      "set nu                 = 0.49"),
                              "subdivisions       = 5, 3",
                              "subdivisions       = 60, 3");
  t                      = replace(replace(t,
                      "subdivisions       = 7, 3",
                      "subdivisions       = 60, 3"),
              "set displacement     = 0, -1e-5",
              "set displacement     = 0, -1e-3");
  const std::string file = source_dir + "/prm/patch-test.prm";
  const Scene       s    = Scene::read_from_string(t, file);

  const double E_s = 210e9, nu_s = 0.3, E_p = 5e6, nu_p = 0.49, H = 0.05,
               w = 0.1;
  const double sigma =
    1e-3 / (H * ((1 - nu_s * nu_s) / E_s + (1 - nu_p * nu_p) / E_p));
  const double slip =
    (nu_p * (1 + nu_p) / E_p - nu_s * (1 + nu_s) / E_s) * sigma * w;
  ASSERT_GT(slip, 0.1 / 60);
  for (const auto &v : three_ways(s, {"Fn"}))
    EXPECT_NEAR(v[0], sigma * w, 1e-6 * sigma * w);

  ContactScene   bodies(s, 0);
  FullOrderModel full(bodies, ObservedDofs(2));
  full.set_state(SceneState(s));
  const ContactSolution answer  = full.solve();
  const SlidingExtent   largest = largest_sliding(bodies.interface(), answer);
  EXPECT_EQ(largest.angle, 0.);
  double largest_slip = 0;
  for (unsigned int k = 0; k < answer.n_nodes(); ++k)
    if (answer.status[k] != ContactStatus::open)
      largest_slip = std::max(largest_slip, std::abs(answer.g[2 * k + 1]));
  EXPECT_NEAR(largest_slip, slip, 1e-6 * slip);

  // The pad as the slave: its edge leaves the steel's face.
  const Scene swapped =
    Scene::read_from_string(replace(t,
                                    "set slave component      = Upper\n"
                                    "  set slave face           = bottom\n"
                                    "  set master component     = Lower\n"
                                    "  set master face          = top",
                                    "set slave component      = Lower\n"
                                    "  set slave face           = top\n"
                                    "  set master component     = Upper\n"
                                    "  set master face          = bottom"),
                            file);
  ContactScene   pad_slave(swapped, 0);
  FullOrderModel model(pad_slave, ObservedDofs(2));
  model.set_state(SceneState(swapped));
  const std::string m = error_of([&] {
    model.solve();
  });
  EXPECT_NE(m.find("off its end"), std::string::npos) << m;
}

// A pin in the bore of a lug (prm/pin.prm), held by contact alone, under a
// load whose line of action misses the bore's centre: the friction in the
// bore holds its torque. Statics: the normal forces pass through the bore's
// centre (its normals are radial), so the contact's moment about it is the
// friction's, F_t R_b, and balances the load's, T = F d_x (2 R / pi - e)
// for the uniform traction F d on the pin's upper half (R = 10 mm, its
// centroid 2 R / pi above the pin's centre, which lies e = 0.05 mm below
// the bore's; R_b = 10.05 mm). The pin needs mu >= mu_s = F_t / F_n, the
// whole patch slipping. Above mu_s the answer stays within small sliding;
// below it the linear problem holds the pin only after it slid by metres
// against the bore's frozen normals (the static equilibrium test, which
// balances resultants only, says the cones hold it), which the models
// refuse (ExcBeyondSmallSliding) and a study counts as without
// equilibrium, or, where the solver fails, leaves out when more friction
// answers within small sliding.
TEST(FloatingBodies, APinInItsBoreSlidesBeyondSmallSlidingBelowStatics)
{
  const Scene    s = scene("pin");
  ContactScene   bodies(s, 0);
  FullOrderModel full(bodies, ObservedDofs(2));
  SceneState     state(s);
  ASSERT_EQ(state.friction_coefficients.size(), 1u);
  full.set_state(state);
  const double F = 2e5, d_x = 0.2 / std::sqrt(1.04), R = 10e-3, e = 0.05e-3,
               R_b = 10.05e-3;
  const double T   = F * d_x * (2 * R / M_PI - e);
  const auto   pin = [&](const ContactSolution &solution) {
    // The contact forces' moment on the pin about the bore's centre.
    double moment = 0;
    for (unsigned int k = 0; k < solution.n_nodes(); ++k)
      {
        const ContactNode &node = bodies.interface().nodes()[k];
        const Tensor<1, 2> f =
          solution.p_n(k) * node.normal + solution.p_t(k) * node.tangent;
        const Tensor<1, 2> r = node.slave.position - Point<2>(0.04, 0.03);
        moment += r[0] * f[1] - r[1] * f[0];
      }
    return moment;
  };
  const ContactSolution nominal = full.solve(); // mu = 0.15
  EXPECT_NEAR(std::abs(pin(nominal)), T, 1e-3 * T);
  EXPECT_NEAR(std::abs(nominal.tangential_force), T / R_b, 1e-3 * T / R_b);
  EXPECT_LT(largest_sliding(bodies.interface(), nominal).angle, 2.);
  const double mu_s = T / R_b / nominal.normal_force;

  state.friction_coefficients = {1.01 * mu_s};
  full.set_state(state);
  const ContactSolution above = full.solve();
  EXPECT_NEAR(std::abs(above.tangential_force), T / R_b, 1e-3 * T / R_b);
  EXPECT_LT(largest_sliding(bodies.interface(), above).angle, 2.);
  EXPECT_GE(above.count(ContactStatus::slip), 1u);

  state.friction_coefficients = {0.93 * mu_s};
  full.set_state(state);
  EXPECT_THROW(full.solve(), ExcBeyondSmallSliding);

  // The study: the same points, and one where the solvers fail.
  const FuzzyParameterSet set =
    fuzzy_parameters(s,
                     "set fuzzy parameters = Lug.E, bore.mu, Pin.press.force\n"
                     "subsection Fuzzy parameter Lug.E\n"
                     "set values = 0.8, 1, 1.2\nset relative = true\nend\n"
                     "subsection Fuzzy parameter bore.mu\n"
                     "set values = 0.05, 0.15, 0.25\nend\n"
                     "subsection Fuzzy parameter Pin.press.force\n"
                     "set values = 1e5, 2e5, 3e5\nend\n");
  FuzzyContactModelSettings settings;
  settings.mesh_refinements = 0;
  settings.contact_solver   = "reduced exact";
  FuzzyContactModel         model(s, set, {"bore.Fn", "bore.Ft"}, settings);
  const std::vector<double> v = model.reduced({210e9, 1.01 * mu_s, F});
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NEAR(std::abs(v[1]), T / R_b, 1e-3 * T / R_b);
  EXPECT_TRUE(model.reduced({210e9, 0.93 * mu_s, F}).empty());
  EXPECT_EQ(model.unanswered().beyond_small_sliding, 1u);
  EXPECT_TRUE(model.full_order({210e9, 0.93 * mu_s, F}).empty());
  EXPECT_EQ(model.unanswered().beyond_small_sliding, 2u);
  // At 0.98 mu_s every solve fails (the active set cycles); more friction
  // answers within small sliding, none beyond it.
  EXPECT_TRUE(model.reduced({210e9, 0.98 * mu_s, F}).empty());
  EXPECT_EQ(model.unanswered().beyond_small_sliding +
              model.unanswered().unsolved_below_sliding_limit,
            3u);
  EXPECT_EQ(model.unanswered().unsolved_near_limit, 0u);
  EXPECT_LE(model.unanswered().sliding_factor, 1.125);
}

// The probes of a failed point (study/sliding_probes.h) give the verdict of
// the first answer upwards, checked against that scan itself over random
// answers that are monotone in the friction (beyond below a factor, within
// above it, failures anywhere), with fewer failed probes where the answer
// beyond comes at twice the friction.
TEST(SlidingProbes, FirstAnswerUpwardsWithFewerFailedProbes)
{
  const std::vector<double> f = sliding_probe_factors(11, 8);
  ASSERT_EQ(f.size(), 13u);
  EXPECT_DOUBLE_EQ(f.front(), 1 + std::ldexp(1., -10));
  EXPECT_DOUBLE_EQ(f[10], 2.);
  EXPECT_DOUBLE_EQ(f.back(), 8.);
  std::mt19937 random(7);
  unsigned int n_beyond = 0, n_within = 0, n_none = 0;
  for (unsigned int trial = 0; trial < 2000; ++trial)
    {
      // Beyond below factor b, within from b on, each failing with
      // probability q.
      const unsigned int          b = random() % (f.size() + 1);
      const double                q = (random() % 5) / 4.;
      std::vector<int>            table(f.size());
      std::bernoulli_distribution fails(q);
      for (unsigned int i = 0; i < f.size(); ++i)
        table[i] = fails(random) ? 0 : i < b ? -1 : 1;
      // The scan upwards.
      unsigned int first = 0;
      while (first < f.size() && table[first] == 0)
        ++first;
      std::vector<bool>    probed(f.size(), false);
      unsigned int         failed = 0;
      const SlidingVerdict v      = probe_sliding(f, [&](const double factor) {
        const unsigned int i =
          std::find(f.begin(), f.end(), factor) - f.begin();
        EXPECT_LT(i, f.size());
        EXPECT_FALSE(probed[i]); // (each factor once)
        probed[i] = true;
        failed += table[i] == 0;
        return table[i];
      });
      EXPECT_EQ(v.failed, failed);
      EXPECT_LE(v.probes, f.size());
      if (first == f.size())
        {
          ++n_none;
          EXPECT_EQ(v.kind, SlidingVerdict::none);
          EXPECT_EQ(v.probes, f.size());
        }
      else if (table[first] < 0)
        {
          ++n_beyond;
          EXPECT_EQ(v.kind, SlidingVerdict::beyond);
        }
      else
        {
          ++n_within;
          EXPECT_EQ(v.kind, SlidingVerdict::within_with_more);
          EXPECT_EQ(v.factor, f[first]);
        }
    }
  EXPECT_GT(n_beyond, 100u);
  EXPECT_GT(n_within, 100u);
  EXPECT_GT(n_none, 50u);
  // Within just above the point: one probe. Beyond at twice the friction
  // after failures everywhere below: two probes, not the eleven upwards.
  std::vector<int> table(f.size(), 1);
  const auto       by_table = [&](const double factor) {
    return table[std::find(f.begin(), f.end(), factor) - f.begin()];
  };
  EXPECT_EQ(probe_sliding(f, by_table).probes, 1u);
  std::fill(table.begin(), table.begin() + 10, 0);
  table[10]                 = -1;
  const SlidingVerdict late = probe_sliding(f, by_table);
  EXPECT_EQ(late.kind, SlidingVerdict::beyond);
  EXPECT_EQ(late.probes, 2u);
  EXPECT_EQ(late.failed, 1u);
}

// ----------------------------------------------------------------------------
// Body weight (gravity)
// ----------------------------------------------------------------------------

namespace
{
  const std::vector<std::string> column_outputs = {"Fn",
                                                   "Column.node(0.05, 1.2).uy",
                                                   "Footing.node(0.05, 0.2).uy",
                                                   "Ft"};
} // namespace

// A steel column standing on a concrete footing under their own weights
// (prm/column.prm; rollers on the sides: a uniaxial state, the column held
// vertically by its contact alone). Statics: the contact force is the
// column's weight rho g W H t, to round-off in every model (the weight's
// resultant along the column's free motion must include the pinned DoF's
// share, which the condensed load vector leaves out). The displacements
// are quadratic in y, which Q2 represents exactly: every node of both
// bodies against the closed form, in every model, the reduced models'
// fields (the VTU output) included.
TEST(Gravity, ColumnOnAFootingAgainstTheUniaxialSolution)
{
  const Scene  s     = scene("column");
  const auto   exact = column_closed_form(s, SceneState(s));
  const double Fn    = 7900 * 9.81 * 0.1 * 1.0 * 1.0; // rho g W H t
  ASSERT_NEAR(exact[0], Fn, 1e-12 * Fn);
  for (const auto &v : three_ways(s, column_outputs))
    {
      EXPECT_NEAR(v[0], Fn, 1e-10 * Fn);
      EXPECT_NEAR(v[1], exact[2], 1e-9 * std::abs(exact[2]));
      EXPECT_NEAR(v[2], exact[1], 1e-9 * std::abs(exact[1]));
      EXPECT_NEAR(v[3], 0., 1e-10 * Fn);
    }

  // Every node's u_y (and u_x = 0) against the closed form: the
  // full-order fields and the exact reduced model's (the column's
  // weight's exact response plus V q).
  ContactScene       bodies(s, 0);
  const Observations outputs(column_outputs, bodies);
  FullOrderModel     full(bodies, outputs.dofs());
  full.set_state(SceneState(s));
  ReducedOrderModel reduced(bodies,
                            component_modes(bodies, ModalParameters()),
                            outputs.dofs(),
                            std::vector<VaryingQuantity>(),
                            ReducedModelSettings());
  reduced.set_state(SceneState(s));
  const auto   fields = {full.solve().displacements,
                         reduced.displacement_fields(
                         reduced.solve(ActiveSetSolver()))};
  const double g = 9.81, Hb = 0.2, p = 7900 * g * 1.0;
  const double Eb = oedometric(30e9, 0.2), Ec = oedometric(210e9, 0.3);
  const auto   u_y = [&](const double y) {
    if (y <= Hb)
      return -(p * y + 2400 * g * (Hb * y - y * y / 2)) / Eb;
    const double s = y - Hb; // in the column
    return exact[1] - 7900 * g * (1.0 * s - s * s / 2) / Ec;
  };
  for (const auto &u : fields)
    {
      ASSERT_EQ(u.size(), 2u);
      double worst = 0;
      for (unsigned int c = 0; c < 2; ++c)
        for (unsigned int i = 0; i < u[c].size(); ++i)
          {
            const Component &body = bodies.component(c);
            const double     y    = body.support_points()[i][1];
            const double expected = body.dof_directions()[i] == 1 ? u_y(y) : 0.;
            worst = std::max(worst, std::abs(u[c][i] - expected));
          }
      EXPECT_LT(worst, 1e-9 * std::abs(exact[2]));
    }
}

// The column of prm/column.prm clamped at its base (no contact), solved
// directly (Component, CHOLMOD): the top's u_y against the uniaxial closed
// form -rho g H^2 / (2 E'), and the base reaction, the traction of the FE
// stress integrated over the base, against the weight rho g W H t (Q2
// represents the quadratic u_y exactly: both to round-off). Pinned instead
// (held by its contact alone), its weight's resultant along its free
// motion is the whole weight, the pin's share included.
TEST(Gravity, ClampedColumnReactionAndShortening)
{
  const Scene          s = scene("column");
  ComponentDescription d = s.components[0];
  d.clamped_faces        = {"bottom"};
  Component column(d, s.plane_model);
  ASSERT_EQ(column.weight_load(), 0);
  SparseCholesky K;
  K.factorize(column.stiffness_matrix(), {}, "the clamped column");
  Vector<double> u = column.load_vector();
  K.solve(u);
  const double rho = 7900, g = 9.81, H = 1.0, W = 0.1, E = 210e9, nu = 0.3;
  const double weight = rho * g * W * H * d.thickness;
  const double Ep     = oedometric(E, nu);
  const double top    = -rho * g * H * H / (2 * Ep);
  EXPECT_NEAR(u[column.vertex_dofs(Point<2>(0.05, 1.2))[1]],
              top,
              1e-10 * std::abs(top));

  // The reaction: the traction sigma n of the FE stress over the base.
  const QGauss<1>                  quadrature(3);
  FEFaceValues<2>                  values(column.mapping(),
                         column.fe(),
                         quadrature,
                         update_gradients | update_normal_vectors |
                           update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const SymmetricTensor<4, 2>      C = elasticity_tensor(s.plane_model, E, nu);
  std::vector<SymmetricTensor<2, 2>> eps(quadrature.size());
  Tensor<1, 2>                       reaction;
  for (const auto &cell : column.dof_handler().active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && face->boundary_id() == 2) // bottom
        {
          values.reinit(cell, face);
          values[displacement].get_function_symmetric_gradients(u, eps);
          for (const unsigned int q : values.quadrature_point_indices())
            reaction += (C * eps[q]) * values.normal_vector(q) * values.JxW(q) *
                        d.thickness;
        }
  EXPECT_NEAR(reaction[1], weight, 1e-10 * weight);
  EXPECT_NEAR(reaction[0], 0., 1e-10 * weight);

  // Held by contact alone (pinned): the whole weight along its free motion.
  Component floating(s.components[0], s.plane_model, 0, nullptr, {"bottom"});
  ASSERT_EQ(floating.free_motion_names(),
            std::vector<std::string>{"translation along (0, 1)"});
  EXPECT_NEAR(floating.rigid_load(0)[0], -weight, 1e-12 * weight);
  // (The condensed nodal forces leave out the pin's share.)
  const double condensed =
    floating.free_motions()[0] * floating.reference_load_vector(0);
  EXPECT_GT(std::abs(condensed + weight), 1e-6 * weight);
}

// step-3's plot of the contact pressure and shear along each face: its
// data, per pair and solver, the slave nodes in order along the pair's
// tangent; pressure and shear times tributary area add up to the pair's
// F_n and F_t (Observations' <pair>.Fn, .Ft), on three-beams' two pairs.
TEST(ContactFacePlot, ItsPressuresAddUpToEachPairsForces)
{
  ContactScene       bodies(scene("three-beams"), 0);
  const Observations outputs({"lower.Fn", "lower.Ft", "upper.Fn", "upper.Ft"},
                             bodies);
  FullOrderModel     full(bodies, outputs.dofs());
  const SceneState   state(bodies.scene());
  full.set_state(state);
  ContactCase c(bodies, state, state.total_force(bodies.scene()));
  SolverRun   run;
  run.solution = full.solve();
  c.runs.push_back(run);
  const std::vector<double> forces = outputs.values(run.solution);
  ASSERT_GT(std::abs(forces[3]), 1e-3 * forces[2]); // upper: friction

  std::istringstream                 data(contact_face_data(c, bodies));
  std::string                        line;
  std::vector<std::array<double, 2>> sums;
  std::vector<double>                last;
  while (std::getline(data, line))
    {
      if (line.rfind("# lower", 0) == 0 || line.rfind("# upper", 0) == 0)
        {
          sums.push_back({{0., 0.}});
          last.clear();
          continue;
        }
      if (line.empty() || line[0] == '#')
        continue;
      std::istringstream row(line);
      double             s, length, pressure, shear;
      row >> s >> length >> pressure >> shear;
      ASSERT_FALSE(sums.empty());
      if (!last.empty())
        {
          EXPECT_GE(s, last.back()) << "nodes out of order along the tangent";
        }
      last.push_back(s);
      const double area = length * bodies.scene().components[0].thickness;
      sums.back()[0] += pressure * area;
      sums.back()[1] += shear * area;
    }
  ASSERT_EQ(sums.size(), 2u);
  for (unsigned int pair = 0; pair < 2; ++pair)
    for (unsigned int i = 0; i < 2; ++i)
      EXPECT_NEAR(sums[pair][i],
                  forces[2 * pair + i],
                  1e-8 * forces[2 * pair]); // (the file's 10 digits)
}

// The stresses the VTU files carry (StressPostprocessor), against closed
// forms. A bar in plane stress stretched uniaxially by hand (eps_xx = e,
// eps_yy = -nu e): sigma_xx = E e and nothing else. The column of
// prm/column.prm clamped at its base, its sides on rollers, under its own
// weight (plane strain): uniaxial strain, sigma_yy = -rho g (y_top - y),
// sigma_xx = sigma_zz = nu / (1 - nu) sigma_yy, sigma_xy = 0, von Mises
// |sigma_yy| (1 - 2 nu) / (1 - nu), pressure -sigma_yy (1 + nu) / (3 (1 -
// nu)); Q2 represents the linear stress exactly, so every Gauss point of
// every cell within round-off.
TEST(Stresses, TheVtuStressesOfAUniaxialColumnAreExact)
{
  const double E = 210e9, nu = 0.3, e = 1e-4;
  Tensor<2, 2> stretch;
  stretch[0][0]       = e;
  stretch[1][1]       = -nu * e;
  const StressState s = stress_state(stretch, PlaneModel::plane_stress, E, nu);
  EXPECT_NEAR(s.xx, E * e, 1e-12 * E * e);
  EXPECT_NEAR(s.yy, 0., 1e-12 * E * e);
  EXPECT_EQ(s.zz, 0.);
  EXPECT_NEAR(s.von_mises(), E * e, 1e-12 * E * e);
  EXPECT_NEAR(s.principal()[0], E * e, 1e-12 * E * e);
  EXPECT_NEAR(s.principal()[1], 0., 1e-12 * E * e);
  EXPECT_NEAR(s.pressure(), -E * e / 3, 1e-12 * E * e);

  const Scene          scene_ = scene("column");
  ComponentDescription d      = scene_.components[0];
  d.clamped_faces             = {"bottom"};
  Component      column(d, scene_.plane_model);
  SparseCholesky K;
  K.factorize(column.stiffness_matrix(), {}, "the clamped column");
  Vector<double> u = column.load_vector();
  K.solve(u);
  const double rho = 7900, g = 9.81, top = 1.2;

  EXPECT_EQ(StressPostprocessor(column, {E}).get_names()[4], "von_mises");
  double worst = 0;
  for_each_gauss_point_stress(
    column,
    u,
    {E},
    [&](const Point<2> &x, const Vector<double> &computed) {
      const double yy = -rho * g * (top - x[1]), xx = nu / (1 - nu) * yy;
      const std::array<double, 8> exact = {
        {xx,
         yy,
         0.,
         xx,
         std::abs(yy) * (1 - 2 * nu) / (1 - nu),
         xx,
         yy,
         -yy * (1 + nu) / (3 * (1 - nu))}};
      ASSERT_EQ(computed.size(), 8u);
      for (unsigned int i = 0; i < 8; ++i)
        worst = std::max(worst, std::abs(computed[i] - exact[i]));
    });
  EXPECT_LT(worst, 1e-8 * rho * g * 1.0) << "largest stress error [Pa]";
}

// The block of prm/slope.prm under its own weight (prm/slope-weight.prm)
// instead of a force: statics' N = W cos 20, T = W sin 20 with W = rho g A t
// in every model, to round-off; with less friction than tan 20 no static
// equilibrium, and the friction it needs is tan 20.
TEST(Gravity, BlockOnASlopeUnderItsWeight)
{
  const double theta = 20 * M_PI / 180;
  const double W     = 7900 * 9.81 * (0.1 * 0.05) * 1.0;
  const auto   read  = [](const double mu) {
    std::ifstream      in(source_dir + "/prm/slope-weight.prm");
    std::ostringstream text;
    text << in.rdbuf();
    return Scene::read_from_string(replace(text.str(),
                                           "set friction coefficient = 0.5",
                                           "set friction coefficient = " +
                                             std::to_string(mu)),
                                   source_dir + "/prm/slope-weight.prm");
  };
  for (const double mu : {0.5, 1.02 * std::tan(theta)})
    for (const auto &v : three_ways(read(mu), {"Fn", "Ft"}))
      {
        EXPECT_NEAR(v[0], W * std::cos(theta), 1e-10 * W) << "mu = " << mu;
        EXPECT_NEAR(std::abs(v[1]), W * std::sin(theta), 1e-10 * W)
          << "mu = " << mu;
      }
  for (const double mu : {0.3, 0.98 * std::tan(theta)})
    {
      const std::string m = error_of([&] {
        three_ways(read(mu), {"Fn"});
      });
      expect_needs_friction(m, std::tan(theta));
    }
}

// The weight as a load of a history: the column and footing weights in a
// first stage (2 steps), a force on the column's top in a second. The
// problem is frictionless, so the end state is that of one proportional
// stage: Fn = W + F in every model.
TEST(Gravity, WeightInALoadStage)
{
  std::ifstream      in(source_dir + "/prm/column.prm");
  std::ostringstream text;
  text << in.rdbuf();
  std::string t = replace(text.str(),
                          "  set gravity       = 0, -9.81\n",
                          "  set gravity       = 0, -9.81\n"
                          "  set load stages   = self, service\n");
  t             = replace(t,
              "  set supports           = left-guide, right-guide\n",
              "  set supports           = left-guide, right-guide\n"
                          "  set loads              = cap\n"
                          "  subsection Load cap\n"
                          "    set face        = top\n"
                          "    set total force = 2e4\n"
                          "  end\n");
  const std::string stages =
    "subsection Stage self\n"
    "  set loads      = Column.weight, Footing.weight\n"
    "  set load steps = 2\n"
    "end\n"
    "subsection Stage service\n"
    "  set loads = Column.cap\n"
    "end\n";
  const Scene  s  = Scene::read_from_string(t + stages, "column-stages.prm");
  const double Fn = 7900 * 9.81 * 0.1 + 2e4;
  for (const auto &v : three_ways(s, {"Fn"}))
    EXPECT_NEAR(v[0], Fn, 1e-10 * Fn);
  // Every load in exactly one stage: the weights too.
  EXPECT_NE(error_of([&] {
              Scene::read_from_string(t +
                                        replace(stages,
                                                "Column.weight, Footing.weight",
                                                "Column.weight"),
                                      "column-stages.prm");
            }).find("the load <Footing.weight> is in no stage"),
            std::string::npos);
}

// What gravity refuses, naming the file and key: a load or support of the
// user called 'weight', a gravity beyond the range, the weight as a
// quantity of its own, a zone's modulus, and a force scaling the loads.
TEST(Gravity, RefusedInput)
{
  std::ifstream      in(source_dir + "/prm/column.prm");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string t    = text.str();
  const auto        fail = [&](const std::string &from, const std::string &to) {
    return error_of([&] {
      Scene::read_from_string(replace(t, from, to), "column.prm");
    });
  };
  EXPECT_NE(fail("  set rho                = 7900\n",
                 "  set rho                = 7900\n"
                 "  set loads              = weight\n"
                 "  subsection Load weight\n"
                 "    set face = top\n"
                 "  end\n")
              .find("Scene file <column.prm>: Component Column: load <weight>: "
                    "with the scene's gravity on"),
            std::string::npos);
  EXPECT_NE(
    fail("set supports           = left-guide, right-guide\n  subsection "
         "Support left-guide",
         "set supports           = weight, right-guide\n  subsection "
         "Support weight")
      .find("Component Column: support <weight>"),
    std::string::npos);
  EXPECT_NE(fail("set gravity       = 0, -9.81", "set gravity = 0, -1e5")
              .find("Scene file <column.prm>: Scene: gravity (its magnitude) "
                    "must lie between 0 and 10000"),
            std::string::npos);
  EXPECT_NE(fail("set gravity       = 0, -9.81", "set gravity = 0, nan")
              .find("Scene: gravity"),
            std::string::npos);
  EXPECT_NE(fail("set gravity       = 0, -9.81", "set gravity = -9.81")
              .find("Scene: gravity"),
            std::string::npos);
  // Without gravity a load may be called 'weight' (prm/slope.prm's is).
  EXPECT_EQ(scene("slope").components[0].loads[0].name, "weight");
  EXPECT_FALSE(scene("slope").components[0].loads[0].is_weight);

  const Scene s = scene("column");
  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("Column.weight.force", s);
            }).find("vary Column.rho"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              SceneQuantity::parse("Column.body.E", s);
            }).find("Vary the modulus of the whole body (Column.E)"),
            std::string::npos);
  EXPECT_EQ(SceneQuantity::parse("Column.body.rho", s).zone, 0);
  SceneState state(s);
  EXPECT_NE(error_of([&] {
              state.scale_forces_to(s, 5e4, "load");
            }).find("has gravity"),
            std::string::npos);
}


// The nearest evaluated point (WarmStarts) against a scan of every kept
// point in scaled distance, the first stored of equally near ones: points
// that come as an optimiser's do (random walks, with jumps and exact
// repeats), more of them than the archive keeps (the oldest overwritten),
// asked at random points and at kept points themselves.
TEST(WarmStarts, TheNearestPointIsAScansAnswer)
{
  const std::vector<double>        widths   = {2., 0.5, 0., 10.};
  const std::size_t                capacity = 300;
  WarmStarts                       archive(widths, capacity);
  std::vector<std::vector<double>> kept(capacity);
  std::vector<std::size_t>         index_of(capacity);
  std::mt19937                     random(7);
  std::uniform_real_distribution<> unit(0., 1.);
  std::vector<double>              x = {0., 0., 0., 0.};
  const auto scaled_distance         = [&](const std::vector<double> &a,
                                   const std::vector<double> &b) {
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      if (widths[i] > 0)
        d += (a[i] / widths[i] - b[i] / widths[i]) *
             (a[i] / widths[i] - b[i] / widths[i]);
    return d;
  };
  std::size_t checked = 0;
  for (std::size_t added = 0; added < 1000; ++added)
    {
      if (added % 97 == 0)
        for (unsigned int i = 0; i < 4; ++i)
          x[i] = widths[i] * unit(random);
      else if (added % 13 != 0) // else: the same point again
        for (unsigned int i = 0; i < 4; ++i)
          x[i] += 0.01 * (widths[i] + 1) * (unit(random) - 0.5);
      std::vector<ContactState> states(1);
      states[0].p.reinit(1);
      states[0].p[0] = added;
      archive.add(x, states);
      kept[added % capacity]     = x;
      index_of[added % capacity] = added;
      const std::size_t n_kept   = std::min(added + 1, capacity);
      for (unsigned int q = 0; q < 3; ++q)
        {
          std::vector<double> y(4);
          for (unsigned int i = 0; i < 4; ++i)
            y[i] = widths[i] * (1.2 * unit(random) - 0.1);
          if (q == 2)
            y = kept[std::size_t(unit(random) * n_kept) % n_kept];
          std::size_t best     = 0;
          double      distance = std::numeric_limits<double>::infinity();
          for (std::size_t e = 0; e < n_kept; ++e)
            if (scaled_distance(y, kept[e]) < distance)
              {
                distance = scaled_distance(y, kept[e]);
                best     = e;
              }
          const std::vector<ContactState> *found = archive.nearest(y);
          ASSERT_NE(found, nullptr);
          EXPECT_EQ(std::size_t((*found)[0].p[0]), index_of[best])
            << "point " << added << ", query " << q;
          ++checked;
        }
    }
  EXPECT_EQ(archive.size(), capacity);
  EXPECT_EQ(checked, 3000u);
}

// Warm starts (contact/contact_workspace.h): the block of prm/slope.prm,
// held by contact alone, pressed and then pushed down the slope in a second
// load stage of three steps. A solve at a neighbouring point (the slope's
// modulus 2 % up, mu 0.55 instead of 0.5) started from the first point's
// states per load step, with the factors kept from it, gives the answer of
// a cold solve (every factor made anew, the frictionless start) to 1e-10 of
// the forces, in fewer iterations; so does FL2C started from the first
// point's forces (to 1e-8, its tolerance being 1e-11).
TEST(WarmStarts, ANeighboursStatesGiveTheColdAnswer)
{
  std::ifstream      in(source_dir + "/prm/slope.prm");
  std::ostringstream text;
  text << in.rdbuf();
  std::string staged = replace(text.str(),
                               "  set contact pairs = block-on-slope\n",
                               "  set contact pairs = block-on-slope\n"
                               "  set load stages   = press, push\n");
  staged             = replace(staged,
                   "  set loads      = weight\n",
                   "  set loads      = weight, push\n"
                               "  subsection Load push\n"
                               "    set face        = uphill\n"
                               "    set total force = 8e2\n"
                               "    set direction   = -0.9397, -0.3420\n"
                               "  end\n");
  staged += "subsection Stage press\n  set loads = Block.weight\nend\n"
            "subsection Stage push\n  set loads = Block.push\n"
            "  set load steps = 3\nend\n";
  const Scene scene =
    Scene::read_from_string(staged, source_dir + "/prm/slope.prm");
  ContactScene         bodies(scene, 0);
  const Observations   outputs({"Fn", "Ft"}, bodies);
  ReducedModelSettings settings;
  ReducedOrderModel    model(bodies,
                          std::vector<ModalBasis>(2),
                          outputs.dofs(),
                          std::vector<VaryingQuantity>(),
                          settings);
  SceneState           first(scene), second(scene);
  SceneQuantity::parse("Slope.E", scene).apply(second, scene, 1.02 * 210e9);
  SceneQuantity::parse("block-on-slope.mu", scene).apply(second, scene, 0.55);

  for (const bool fl2c : {false, true})
    {
      FL2CParameters parameters;
      parameters.tolerance = 1e-11;
      const ActiveSetSolver exact;
      const FL2CSolver      regulators(parameters);
      const ContactSolver  &solver =
        fl2c ? static_cast<const ContactSolver &>(regulators) : exact;
      ContactWorkspace &workspace = model.workspace();

      // The second point cold.
      workspace.clear();
      workspace.start.clear();
      model.set_state(second);
      const ContactSolution cold = model.solve(solver);
      // The first point, then the second from its states and factors.
      workspace.clear();
      model.set_state(first);
      model.solve(solver);
      ASSERT_EQ(workspace.converged.size(), 4u);
      workspace.start = workspace.converged;
      model.set_state(second);
      const ContactSolution warm = model.solve(solver);

      Vector<double> difference = warm.p;
      difference -= cold.p;
      EXPECT_LE(difference.linfty_norm(),
                (fl2c ? 1e-8 : 1e-10) * cold.p.linfty_norm())
        << solver.name();
      // (FL2C makes at least one sweep and one check per load step
      // either way.)
      if (!fl2c)
        {
          EXPECT_LT(warm.iterations, cold.iterations);
        }
      EXPECT_GT(cold.p.linfty_norm(), 0.);
      // FL2C from a start that passes its test as it is (this point's own
      // converged states) still makes one sweep and one coarse correction
      // per load step: a residual within the tolerance is not the exact
      // answer (on the punch, the free motion was 1e-9 m off).
      if (fl2c)
        {
          workspace.start             = workspace.converged;
          const ContactSolution again = model.solve(solver);
          EXPECT_GE(again.iterations, 2 * workspace.start.size());
        }
    }
}

namespace
{
  // The largest difference between the bounds of two step-4 results.json
  // texts (every output, level and method), relative to the output's
  // largest value over all levels and methods; @p where names it.
  double
  largest_bound_difference(const std::string &one,
                           const std::string &two,
                           std::string       &where)
  {
    const nlohmann::json a     = nlohmann::json::parse(one);
    const nlohmann::json b     = nlohmann::json::parse(two);
    double               worst = 0;
    AssertThrow(a["outputs"].size() == b["outputs"].size(),
                ExcMessage("the runs have different outputs"));
    for (unsigned int k = 0; k < a["outputs"].size(); ++k)
      {
        const nlohmann::json &x = a["outputs"][k], &y = b["outputs"][k];
        // The output's range (floored at 1e-9 of its magnitude, for an
        // output the parameters cannot change).
        double lo = std::numeric_limits<double>::infinity(), hi = -lo,
               magnitude = 0;
        for (const char *key : {"lower", "upper"})
          for (const double v : x[key].get<std::vector<double>>())
            {
              lo        = std::min(lo, v);
              hi        = std::max(hi, v);
              magnitude = std::max(magnitude, std::abs(v));
            }
        const double scale = std::max(hi - lo, 1e-9 * magnitude);
        for (const char *key : {"lower",
                                "upper",
                                "vertex_lower",
                                "vertex_upper",
                                "reference_lower",
                                "reference_upper"})
          {
            if (!x.contains(key) || x[key].is_null())
              continue;
            const auto u = x[key].get<std::vector<double>>();
            const auto v = y[key].get<std::vector<double>>();
            AssertThrow(u.size() == v.size(),
                        ExcMessage("the runs have different levels"));
            for (unsigned int i = 0; i < u.size(); ++i)
              {
                const double d =
                  scale > 0 ? std::abs(u[i] - v[i]) / scale : u[i] != v[i];
                if (d > worst)
                  {
                    worst = d;
                    where = x["name"].get<std::string>() + " " + key +
                            " level " + std::to_string(i) + ": " +
                            Format::scientific(u[i], 17) + " and " +
                            Format::scientific(v[i], 17);
                  }
              }
          }
      }
    return worst;
  }
} // namespace


// tests/compare_mpi_runs.cmake runs this test on the results.json of a
// one-process and a two-process step-4 run (FUZZYCONTACT_RESULTS_NP1 and
// _NP2): their bounds agree to 1e-6 of each output's range. The contact
// solvers start each evaluation from its nearest neighbour's state
// (study/warm_starts.h), and the ranks do not see the same neighbours, so
// the answers agree to round-off, not bit for bit; where a bound lies at a
// kink the search locates it only to its refinement step (1e-6 of the
// widths), and a round-off difference can end it elsewhere within that
// step (the Hertz roller's max_pressure: 2.8e-7 of its range). Without the
// variables it checks the comparison itself.
TEST(MpiRuns, BoundsAgreeToRoundOff)
{
  const char *np1 = std::getenv("FUZZYCONTACT_RESULTS_NP1");
  const char *np2 = std::getenv("FUZZYCONTACT_RESULTS_NP2");
  std::string where;
  if (np1 == nullptr || np2 == nullptr)
    {
      const std::string one =
        R"({"outputs": [{"name": "Fn", "lower": [1.0, 2.0],
            "upper": [4.0, 3.0], "vertex_lower": [1.0, 2.0],
            "vertex_upper": [4.0, 3.0]}]})";
      std::string two = one;
      EXPECT_EQ(largest_bound_difference(one, two, where), 0.);
      two.replace(two.find("[4.0, 3.0]}"), 11, "[4.0, 3.0000001]}");
      EXPECT_NEAR(largest_bound_difference(one, two, where), 1e-7 / 3, 1e-15);
      EXPECT_EQ(where.substr(0, 22), "Fn vertex_upper level ");
      return;
    }
  const double worst = largest_bound_difference(Input::read_text_file(np1),
                                                Input::read_text_file(np2),
                                                where);
  EXPECT_LE(worst, 1e-6) << where;
  std::cout << "largest difference " << worst << " of an output's range ("
            << where << ")" << std::endl;
}
