// Tests of the foundation: scenes read from parameter files (and the
// rejection of bad ones), component assembly, and the modal solver, each
// against an independent value.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/row_updated_lu.h>
#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/base/sparse_direct_solver.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/fe/beam_theory.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/fe/hertz_theory.h>
#include <fuzzycontact/fe/patch_test.h>
#include <fuzzycontact/fe/stress_state.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <gtest/gtest.h>

#include "gauss_point_stresses.h"
#include "test_utilities.h"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <tuple>
#include <unistd.h>

using namespace FuzzyContact;
using namespace FuzzyContact::Testing;

namespace
{

  // A one-beam scene; tests replace parts of it to make it wrong.
  const std::string cantilever_scene = R"(
subsection Scene
  set name       = cantilever
  set components = beam
end
subsection Component beam
  set lower left corner  = 0, 0
  set upper right corner = 0.2, 0.008
  set subdivisions       = 25, 1
  set fe degree          = 2
  set clamped faces      = left
  set loads              = tip
  subsection Load tip
    set face        = right
    set total force = 1000
    set direction   = 0, -1
  end
end
)";


  // The message of the exception that reading @p text throws ("" if none).
  std::string
  read_error(const std::string &text)
  {
    try
      {
        const Scene scene = Scene::read_from_string(text, "test.prm");
        // Some errors only show when the mesh is built.
        for (const auto &c : scene.components)
          Component component(c, scene.plane_model);
      }
    catch (const dealii::ExceptionBase &e)
      {
        return Input::message_of(e);
      }
    return "";
  }

  double
  max_abs_entry(const dealii::SparseMatrix<double> &A)
  {
    double m = 0;
    for (const auto &entry : A)
      m = std::max(m, std::abs(entry.value()));
    return m;
  }
} // namespace


// ----------------------------------------------------------------------------
// Scenes
// ----------------------------------------------------------------------------

TEST(Scene, ReadsTheDefaultScenes)
{
  for (const std::string name : {"overlap", "stacked"})
    {
      const Scene scene = Scene::read(source_dir + "/prm/" + name + ".prm");
      EXPECT_EQ(scene.name, name);
      EXPECT_EQ(scene.plane_model, PlaneModel::plane_stress);
      ASSERT_EQ(scene.components.size(), 2u);
      const ComponentDescription &p1 = scene.components[0];
      EXPECT_EQ(p1.name, "P1");
      EXPECT_NEAR(p1.length(), 0.2, 1e-15);
      EXPECT_NEAR(p1.height(), 0.008, 1e-15);
      EXPECT_NEAR(p1.lower_left[1], 1e-8, 1e-20);
      ASSERT_EQ(p1.zones.size(), 1u);
      EXPECT_TRUE(p1.implicit_zone);
      EXPECT_EQ(p1.zones[0].youngs_modulus, 210e9);
      EXPECT_EQ(p1.zones[0].density, 7900);
      ASSERT_EQ(p1.loads.size(), 1u);
      EXPECT_EQ(p1.loads[0].total_force, 50000);
      EXPECT_EQ(p1.loads[0].face, "right");
      EXPECT_EQ(p1.loads[0].direction[1], -1.);
      ASSERT_EQ(scene.contact_pairs.size(), 1u);
      const ContactPairDescription &pair = scene.contact_pairs[0];
      EXPECT_EQ(pair.slave_component, "P1");
      EXPECT_EQ(pair.slave_face, "bottom");
      EXPECT_EQ(pair.master_component, "P2");
      EXPECT_EQ(pair.master_face, "top");
      EXPECT_EQ(pair.friction_coefficient, 0.3);
      EXPECT_FALSE(pair.has_initial_gap);
    }
  const Scene overlap = Scene::read(source_dir + "/prm/overlap.prm");
  EXPECT_EQ(overlap.components[1].clamped_faces[0], "right");
  EXPECT_NEAR(overlap.components[1].lower_left[0], 0.1, 1e-15);
}

TEST(Scene, ZonesInheritAndOverride)
{
  const Scene scene =
    Scene::read_from_string(replace(cantilever_scene,
                                    "  set loads              = tip",
                                    R"(  set E = 200e9
  set zones = root, tip_half
  subsection Zone root
    set x range = 0, 0.1
    set rho     = 8000
  end
  subsection Zone tip_half
    set x range = 0.1, 0.2
    set E       = 100e9
  end
  set loads = tip)"));
  const auto &zones = scene.components[0].zones;
  ASSERT_EQ(zones.size(), 2u);
  EXPECT_EQ(zones[0].youngs_modulus, 200e9);
  EXPECT_EQ(zones[0].density, 8000);
  EXPECT_EQ(zones[1].youngs_modulus, 100e9);
  EXPECT_EQ(zones[1].density, 7900);
  EXPECT_EQ(zones[1].x_range[0], 0.1);
  EXPECT_EQ(zones[1].y_range[1], 0.008);
  EXPECT_EQ(scene.components[0].zone_index("tip_half"), 1u);
}

// A support that the clamps and the supports before it leave nothing to
// hold is refused when the scene is read, naming the scene file.
TEST(Scene, ASupportWithNothingToHoldIsRefusedNamingTheFile)
{
  const std::string text =
    replace(cantilever_scene,
            "  set clamped faces      = left",
            "  set clamped faces = left\n  set supports = again\n"
            "  subsection Support again\n    set face = left\n"
            "    set fixed components = y\n  end");
  std::string message;
  try
    {
      Scene::read_from_string(text, "test.prm");
    }
  catch (const dealii::ExceptionBase &e)
    {
      message = Input::message_of(e);
    }
  EXPECT_NE(message.find("test.prm"), std::string::npos) << message;
  EXPECT_NE(message.find("Component beam, support again: the supports "
                         "listed before it already hold every DoF it fixes "
                         "on the face 'left'"),
            std::string::npos)
    << message;
  // A support on another face, or fixing a component the clamp does not
  // (none here), is fine: the cantilever with a roller on its top face.
  EXPECT_NO_THROW(Scene::read_from_string(
    replace(cantilever_scene,
            "  set clamped faces      = left",
            "  set clamped faces = left\n  set supports = roller\n"
            "  subsection Support roller\n    set face = top\n"
            "    set fixed components = y\n  end"),
    "test.prm"));
}

// Each bad input gives a message that names the parameter and the problem.
struct BadInput
{
  std::string name;
  std::string from;
  std::string to;
  std::string expected_message;
};

void
PrintTo(const BadInput &c, std::ostream *out)
{
  *out << c.name;
}

class SceneBadInput : public ::testing::TestWithParam<BadInput>
{
};

TEST_P(SceneBadInput, IsRejectedWithAClearMessage)
{
  const BadInput   &c = GetParam();
  const std::string message =
    read_error(replace(cantilever_scene, c.from, c.to));
  EXPECT_NE(message.find(c.expected_message), std::string::npos)
    << "message was: " << message;
}

INSTANTIATE_TEST_SUITE_P(
  Foundation,
  SceneBadInput,
  ::testing::Values(
    BadInput{"unknown_key",
             "set fe degree          = 2",
             "set fe degre = 2",
             "No entry with name <fe degre>"},
    BadInput{
      "malformed_number",
      "set total force = 1000",
      "set total force = 1e3x",
      "The entry value 1e3x for the entry named total force does not match"},
    BadInput{"nan",
             "set total force = 1000",
             "set total force = nan",
             "The entry value nan for the entry named total force does not "
             "match"},
    BadInput{"nan_in_zone",
             "  set loads              = tip",
             "  set zones = z\n  subsection Zone z\n set E = nan\n end\n"
             "  set loads = tip",
             "Component beam, zone z: E: <nan> is not a finite number"},
    BadInput{"negative_modulus",
             "set fe degree          = 2",
             "set fe degree = 2\n set E = -210e9",
             "Component beam: E must be positive, got -2.1e+11"},
    BadInput{"zero_modulus",
             "set fe degree          = 2",
             "set fe degree = 2\n set E = 0",
             "Component beam: E must be positive, got 0"},
    BadInput{"zero_density",
             "set fe degree          = 2",
             "set fe degree = 2\n set rho = 0",
             "Component beam: rho must be positive"},
    BadInput{"poisson_out_of_range",
             "set fe degree          = 2",
             "set fe degree = 2\n set nu = 0.5",
             "Component beam: nu must lie in (-1, 0.5)"},
    BadInput{"zero_thickness",
             "set fe degree          = 2",
             "set fe degree = 2\n set thickness = 0",
             "Component beam: thickness must be positive, got 0"},
    BadInput{"negative_length",
             "set upper right corner = 0.2, 0.008",
             "set upper right corner = -0.2, 0.008",
             "Component beam: length (upper right x - lower left x) must be "
             "positive, got -0.2"},
    BadInput{"zero_height",
             "set upper right corner = 0.2, 0.008",
             "set upper right corner = 0.2, 0",
             "Component beam: height (upper right y - lower left y) must be "
             "positive, got 0"},
    BadInput{"zero_subdivisions",
             "set subdivisions       = 25, 1",
             "set subdivisions = 25, 0",
             "Component beam: subdivisions must be positive integers"},
    BadInput{"missing_subdivisions",
             "set subdivisions       = 25, 1",
             "",
             "subdivisions"},
    BadInput{"clamp_face_that_does_not_exist",
             "set clamped faces      = left",
             "set clamped faces = front",
             "Component beam: clamped faces: <front> is not a face of a "
             "rectangular component"},
    BadInput{"load_face_that_does_not_exist",
             "set face        = right",
             "set face = tip",
             "Component beam, load tip: face: <tip> is not a face of a "
             "rectangular component"},
    BadInput{"pressure_and_total_force",
             "set direction   = 0, -1",
             "set direction = 0, -1\n    set pressure = 1e6",
             "Component beam, load tip: set either total force or pressure, "
             "not both."},
    BadInput{"zero_load_direction",
             "set direction   = 0, -1",
             "set direction = 0, 0",
             "Component beam, load tip: direction must not be the zero "
             "vector"},
    BadInput{"contact_with_missing_component",
             "  set components = beam",
             "  set components = beam\n  set contact pairs = c\nend\n"
             "subsection Contact c\n  set slave component = beam\n"
             "  set master component = wall",
             "Contact c: there is no component called <wall>"},
    BadInput{"contact_face_that_does_not_exist",
             "  set components = beam",
             "  set components = beam\n  set contact pairs = c\nend\n"
             "subsection Contact c\n  set slave component = beam\n"
             "  set master component = beam\n  set master face = side",
             "Contact c: master face: <side> is not a face of a rectangular "
             "component; use left, right, bottom or top."},
    BadInput{"negative_friction",
             "  set components = beam",
             "  set components = beam\n  set contact pairs = c\nend\n"
             "subsection Contact c\n  set slave component = beam\n"
             "  set master component = beam\n"
             "  set friction coefficient = -0.1",
             "Contact c: friction coefficient must not be negative"},
    BadInput{"undeclared_component_section",
             "subsection Component beam",
             "subsection Component P7\nend\nsubsection Component beam",
             "There is no such subsection to be entered: Component P7"},
    BadInput{"zones_with_a_hole",
             "  set loads              = tip",
             "  set zones = a\n  subsection Zone a\n set x range = 0, 0.1\n "
             "end\n  set loads = tip",
             "lies in no material zone"},
    BadInput{"zone_off_the_mesh_lines",
             "  set loads              = tip",
             "  set zones = a, b\n  subsection Zone a\n set x range = 0, 0.101"
             "\n end\n subsection Zone b\n set x range = 0.101, 0.2\n end\n"
             "  set loads = tip",
             "Component beam, zone a: its edges do not lie on mesh lines"},
    BadInput{"duplicate_names",
             "  set loads              = tip",
             "  set loads = tip, tip",
             "Component beam: loads: the name <tip> appears twice"},
    BadInput{"support_without_effect",
             "  set clamped faces      = left",
             "  set clamped faces = left\n  set supports = again\n"
             "  subsection Support again\n    set face = left\n"
             "    set fixed components = y\n  end",
             "Component beam, support again: the supports listed before it "
             "already hold every DoF it fixes on the face 'left'"}),
  [](const ::testing::TestParamInfo<BadInput> &info) {
    return info.param.name;
  });


// ----------------------------------------------------------------------------
// Components
// ----------------------------------------------------------------------------

namespace
{
  // The cantilever of the tests, split into three zones with different
  // materials (Poisson's ratio too, so that the zone matrices differ in
  // shape, not just in scale).
  Scene
  three_zone_scene(const std::string &clamps = "left")
  {
    return Scene::read_from_string(
      replace(replace(cantilever_scene,
                      "set clamped faces      = left",
                      "set clamped faces = " + clamps),
              "  set loads              = tip",
              R"(  set zones = a, b, c
  subsection Zone a
    set x range = 0, 0.08
    set E = 210e9
  end
  subsection Zone b
    set x range = 0.08, 0.16
    set E = 150e9
    set nu = 0.25
    set rho = 3000
  end
  subsection Zone c
    set x range = 0.16, 0.2
    set E = 70e9
    set nu = 0.33
    set rho = 2700
  end
  set loads = tip)"));
  }
} // namespace

// K and M against energies computed by hand: an affine displacement field
// (constant strain) is represented exactly by the Q2 interpolation, so
// u^T K v = sum_z A_z t sigma_z(u) : eps(v) over the zones (each with its own
// E and nu), in both 2D models, and for a translation u^T M u = sum_z rho_z
// A_z t, the total mass. Unclamped, so that no DoF is eliminated.
TEST(Component, StiffnessAndMassGiveTheEnergiesOfAffineFields)
{
  for (const PlaneModel model :
       {PlaneModel::plane_stress, PlaneModel::plane_strain})
    {
      Scene scene                   = three_zone_scene("");
      scene.plane_model             = model;
      const ComponentDescription &d = scene.components[0];
      const Component             component(d, model, 1);
      const auto                  field = [&](const std::array<double, 3> &e) {
        // u_x = e11 x + e12 y, u_y = e12 x + e22 y
        dealii::Vector<double> u(component.n_dofs());
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            const auto &x = component.support_points()[i];
            u[i]          = component.dof_directions()[i] == 0
                                               ? e[0] * x[0] + e[1] * x[1]
                                               : e[1] * x[0] + e[2] * x[1];
          }
        return u;
      };
      // sigma(a) : eps(b) for constant strains a, b (Voigt-free, by hand).
      const auto bilinear = [&](const MaterialZone          &z,
                                const std::array<double, 3> &a,
                                const std::array<double, 3> &b) {
        double E = z.youngs_modulus, nu = z.poissons_ratio;
        if (model == PlaneModel::plane_strain)
          {
            E  = E / (1 - nu * nu);
            nu = nu / (1 - nu);
          }
        const double c = E / (1 - nu * nu);
        return c * (a[0] * b[0] + a[2] * b[2] +
                    nu * (a[0] * b[2] + a[2] * b[0])) +
               2 * E / (1 + nu) * a[1] * b[1];
      };
      const std::array<double, 3> a   = {{1e-3, -4e-4, 2.5e-4}},
                                  b   = {{-3e-4, 6e-4, 8e-4}};
      const dealii::Vector<double> ua = field(a), ub = field(b);
      dealii::Vector<double>       Kub(component.n_dofs());
      component.stiffness_matrix().vmult(Kub, ub);
      double expected_ab = 0, expected_bb = 0, mass = 0;
      for (unsigned int z = 0; z < d.zones.size(); ++z)
        {
          const double volume = d.zone_area(z) * d.thickness;
          expected_ab += volume * bilinear(d.zones[z], a, b);
          expected_bb += volume * bilinear(d.zones[z], b, b);
          mass += d.zones[z].density * volume;
        }
      EXPECT_NEAR(ua * Kub, expected_ab, 1e-10 * expected_bb);
      EXPECT_NEAR(ub * Kub, expected_bb, 1e-10 * expected_bb);
      dealii::Vector<double> translation(component.n_dofs()),
        Mt(component.n_dofs());
      for (unsigned int i = 0; i < translation.size(); ++i)
        translation[i] = component.dof_directions()[i] == 0 ? 1. : 0.;
      component.mass_matrix().vmult(Mt, translation);
      EXPECT_NEAR(translation * Mt, mass, 1e-12 * mass);
    }
}

TEST(Component, UnclampedStiffnessHasExactlyTheThreeRigidBodyModes)
{
  for (const PlaneModel model :
       {PlaneModel::plane_stress, PlaneModel::plane_strain})
    {
      Scene scene       = three_zone_scene("");
      scene.plane_model = model;
      const Component        component(scene.components[0], scene.plane_model);
      const auto            &K     = component.stiffness_matrix();
      const double           scale = K.linfty_norm();
      dealii::Vector<double> Kr(component.n_dofs());
      for (const auto &r : component.rigid_body_motions())
        {
          K.vmult(Kr, r);
          EXPECT_LT(Kr.linfty_norm(), 1e-12 * scale * r.linfty_norm());
        }

      // And nothing else: with a negative shift, ARPACK finds three zero
      // eigenvalues and then a clearly positive one.
      ModalParameters p;
      p.n_modes = 4;
      p.shift   = -1e6;
      const ModalBasis basis =
        ModalSolver(p).solve(K, component.mass_matrix(), "free beam");
      for (unsigned int j = 0; j < 3; ++j)
        EXPECT_LT(std::abs(basis.eigenvalues[j]), 1e-6 * basis.eigenvalues[3]);
      EXPECT_GT(basis.frequencies()[3], 500.); // first free-free bending mode
    }
}

TEST(Component, ZoneMatricesSumToTheDirectAssembly)
{
  const Scene scene = three_zone_scene();
  Component   component(scene.components[0], scene.plane_model, 1);
  // Change the materials away from the declared ones first, so that the sum
  // uses set_zone_materials() as the reanalysis will.
  component.set_zone_materials({190e9, 160e9, 80e9}, {7000, 3100, 2600});

  dealii::SparseMatrix<double> K, M;
  component.assemble_directly(K, M);
  for (const auto &[sum, direct] :
       {std::make_pair(&component.stiffness_matrix(), &K),
        std::make_pair(&component.mass_matrix(), &M)})
    {
      double worst = 0;
      for (const auto &entry : *direct)
        worst = std::max(worst,
                         std::abs(entry.value() -
                                  sum->el(entry.row(), entry.column())));
      EXPECT_LT(worst, 1e-14 * max_abs_entry(*direct));
    }

  // Each zone matrix lives on its own cells only and is assembled with unit
  // density, so a unit x-translation u has u^T M_z u = area of zone z times
  // t (= 1 here). The clamped DoFs are left out of u; they touch zone a only.
  const dealii::Vector<double> ones = [&] {
    dealii::Vector<double> v(component.n_dofs());
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] =
        (component.dof_directions()[i] == 0 && !component.is_constrained(i))
          ? 1.
          : 0.;
    return v;
  }();
  EXPECT_NEAR(component.zone_mass_matrix(2).matrix_norm_square(ones),
              0.04 * 0.008,
              1e-15);
  EXPECT_NEAR(component.zone_mass_matrix(1).matrix_norm_square(ones),
              0.08 * 0.008,
              1e-15);
}

// A component built without its matrices (an MPI rank that does not build
// its reduced model) assembles them where they are first asked for, and
// then has the very numbers of one assembled when it was built, also after
// a change of materials made before: the face loads alone without any
// matrix, the loads of a prescribed displacement (patch test, upper body)
// with them.
TEST(Component, AssembledOnFirstUseAsWhenBuilt)
{
  const Scene patch =
    Scene::read(std::string(FUZZYCONTACT_SOURCE_DIR) + "/prm/patch-test.prm");
  const Scene zones = three_zone_scene();
  for (const ComponentDescription *d :
       {&zones.components[0], &patch.components[0], &patch.components[1]})
    {
      const PlaneModel model =
        d == &zones.components[0] ? zones.plane_model : patch.plane_model;
      Component built(*d, model, 1);
      Component lazy(*d, model, 1, nullptr, {}, /*assemble=*/false);
      EXPECT_TRUE(built.is_assembled());
      EXPECT_FALSE(lazy.is_assembled());
      bool displaced = false;
      for (const EdgeLoad &load : d->loads)
        displaced = displaced || load.is_displacement;
      for (unsigned int l = 0; l < d->loads.size() && !displaced; ++l)
        EXPECT_EQ(lazy.unit_load_vector(l), built.unit_load_vector(l));
      EXPECT_EQ(lazy.is_assembled(), false) << d->name;

      std::vector<double> moduli    = built.zone_moduli(),
                          densities = built.zone_densities();
      for (unsigned int z = 0; z < moduli.size(); ++z)
        {
          moduli[z] *= 1.1 + 0.1 * z;
          densities[z] *= 0.9;
        }
      built.set_zone_materials(moduli, densities);
      lazy.set_zone_materials(moduli, densities);
      EXPECT_EQ(lazy.load_vector(), built.load_vector()) << d->name;
      EXPECT_EQ(lazy.is_assembled(), displaced) << d->name;
      for (const auto &[a, b] :
           {std::make_pair(&lazy.stiffness_matrix(), &built.stiffness_matrix()),
            std::make_pair(&lazy.mass_matrix(), &built.mass_matrix())})
        {
          ASSERT_EQ(a->n_nonzero_elements(), b->n_nonzero_elements());
          for (const auto &entry : *b)
            EXPECT_EQ(a->el(entry.row(), entry.column()), entry.value());
        }
      EXPECT_TRUE(lazy.is_assembled());
    }
}

// The forces of a prescribed displacement handed over from a component
// that assembled them (another MPI rank's) give the loads without any
// assembly, the same numbers, also after a change of materials.
TEST(Component, DisplacementLoadsGivenNeedNoAssembly)
{
  const Scene patch =
    Scene::read(std::string(FUZZYCONTACT_SOURCE_DIR) + "/prm/patch-test.prm");
  const ComponentDescription &d = patch.components[0];
  Component                   built(d, patch.plane_model, 1);
  Component lazy(d, patch.plane_model, 1, nullptr, {}, /*assemble=*/false);
  ASSERT_EQ(built.displacement_zone_loads().size(), 1u);
  lazy.set_displacement_zone_loads(built.displacement_zone_loads());
  for (unsigned int l = 0; l < d.loads.size(); ++l)
    EXPECT_EQ(lazy.unit_load_vector(l), built.unit_load_vector(l));
  built.set_zone_materials({250e9}, {7000});
  lazy.set_zone_materials({250e9}, {7000});
  EXPECT_EQ(lazy.load_vector(), built.load_vector());
  EXPECT_GT(lazy.load_vector().linfty_norm(), 0.);
  EXPECT_FALSE(lazy.is_assembled());
  // Assembled later (an independent analysis), the forces stay the same.
  lazy.stiffness_matrix();
  EXPECT_EQ(lazy.displacement_zone_loads(), built.displacement_zone_loads());
}

TEST(Component, EdgeLoadHasTheDeclaredResultant)
{
  const Scene     scene = three_zone_scene();
  const Component component(scene.components[0], scene.plane_model, 1);
  double          fx = 0, fy = 0;
  for (unsigned int i = 0; i < component.n_dofs(); ++i)
    (component.dof_directions()[i] == 0 ? fx : fy) +=
      component.load_vector()[i];
  EXPECT_NEAR(fx, 0., 1e-10);
  EXPECT_NEAR(fy, -1000., 1e-10);
}

TEST(Component, FindsVertexDofs)
{
  const Scene     scene = three_zone_scene();
  const Component component(scene.components[0], scene.plane_model);
  const auto      dofs = component.vertex_dofs(dealii::Point<2>(0.2, 0.));
  EXPECT_EQ(component.dof_directions()[dofs[0]], 0);
  EXPECT_EQ(component.dof_directions()[dofs[1]], 1);
  EXPECT_NEAR(component.support_points()[dofs[1]].distance(
                dealii::Point<2>(0.2, 0.)),
              0.,
              1e-15);
  EXPECT_THROW(component.vertex_dofs(dealii::Point<2>(0.3, 0.)),
               dealii::ExceptionBase);
}


// ----------------------------------------------------------------------------
// Beam theory
// ----------------------------------------------------------------------------

TEST(BeamTheory, EulerBernoulliRootsAreTheTabulatedOnes)
{
  // beta_n L of a cantilever: 1.875104, 4.694091, 7.854757, 10.995541.
  BeamTheory::Beam beam{1, 0.01, 1, 1, 0.3, 1, PlaneModel::plane_stress};
  const double     c =
    std::sqrt(beam.effective_modulus() * beam.second_moment_of_area() /
              (beam.density * beam.area())) /
    (2 * M_PI);
  const double roots[] = {1.875104068711961,
                          4.694091132974175,
                          7.854757438237613,
                          10.99554073487547};
  for (unsigned int n = 1; n <= 4; ++n)
    EXPECT_NEAR(BeamTheory::euler_bernoulli_frequency(beam, n) / c,
                roots[n - 1] * roots[n - 1],
                1e-9 * roots[n - 1] * roots[n - 1]);
}

TEST(BeamTheory, TimoshenkoTendsToEulerBernoulliForSlenderBeams)
{
  for (const double slenderness : {25., 250., 2500.})
    {
      BeamTheory::Beam beam{0.2,
                            0.2 / slenderness,
                            1,
                            210e9,
                            0.3,
                            7900,
                            PlaneModel::plane_stress};
      for (unsigned int n = 1; n <= 4; ++n)
        {
          const double eb = BeamTheory::euler_bernoulli_frequency(beam, n);
          const double ti = BeamTheory::timoshenko_frequency(beam, n);
          EXPECT_LT(ti, eb);
          // The shear and rotary-inertia correction is of relative order
          // (n h / L)^2.
          EXPECT_LT(1 - ti / eb, 6. * std::pow(n / slenderness, 2));
          EXPECT_GT(1 - ti / eb, 0.05 * std::pow(n / slenderness, 2));
        }
    }
}


// ----------------------------------------------------------------------------
// Modal solver
// ----------------------------------------------------------------------------

TEST(ModalSolver, FirstBendingFrequencyWithinOnePercentOfTimoshenko)
{
  const Scene scene = Scene::read(source_dir + "/prm/overlap.prm");
  for (const PlaneModel model :
       {PlaneModel::plane_stress, PlaneModel::plane_strain})
    {
      // 300 x 8 cells of Q2, 20k DoFs.
      const Component component(scene.components[0], model, 2);
      ModalParameters p;
      p.n_modes = 3;
      const ModalBasis basis =
        ModalSolver(p).solve(component.stiffness_matrix(),
                             component.mass_matrix(),
                             "P1");
      const auto beam = BeamTheory::Beam::of(scene.components[0], model);
      EXPECT_NEAR(basis.frequencies()[0] /
                    BeamTheory::timoshenko_frequency(beam, 1),
                  1.,
                  0.01);
      // The converged plane-stress value (Q2 on 1000 x 40 cells, 324k DoFs,
      // doc/modal-analysis.md) is 166.436 Hz. Plane strain is plane stress
      // with E / (1 - nu^2) and nu / (1 - nu), so it is not just that value
      // scaled by 1 / sqrt(1 - nu^2) = 174.47 Hz: about 174.5 Hz.
      if (model == PlaneModel::plane_stress)
        EXPECT_NEAR(basis.frequencies()[0], 166.436, 0.01);
      else
        EXPECT_NEAR(basis.frequencies()[0], 174.5, 0.1);
    }
}

TEST(ModalSolver, AgreesWithDenseLapackOnTheFreeDofsAndHasNoSpuriousModes)
{
  // Dense generalised eigenproblem on the unconstrained DoFs only: an
  // independent solver that knows nothing of the zero-mass treatment of the
  // clamped DoFs. ARPACK's nine modes must be exactly its nine lowest.
  const Scene               scene = three_zone_scene();
  const Component           component(scene.components[0], scene.plane_model);
  std::vector<unsigned int> free_dofs;
  for (unsigned int i = 0; i < component.n_dofs(); ++i)
    if (!component.is_constrained(i))
      free_dofs.push_back(i);
  const unsigned int               n = free_dofs.size();
  dealii::LAPACKFullMatrix<double> K(n, n), M(n, n);
  for (unsigned int a = 0; a < n; ++a)
    for (unsigned int b = 0; b < n; ++b)
      {
        K(a, b) = component.stiffness_matrix().el(free_dofs[a], free_dofs[b]);
        M(a, b) = component.mass_matrix().el(free_dofs[a], free_dofs[b]);
      }
  std::vector<dealii::Vector<double>> vectors(n, dealii::Vector<double>(n));
  K.compute_generalized_eigenvalues_symmetric(M, vectors);
  std::vector<double> dense;
  for (unsigned int j = 0; j < n; ++j)
    dense.push_back(K.eigenvalue(j).real());
  std::sort(dense.begin(), dense.end());

  for (const double shift : {0., 4e8})
    {
      ModalParameters p;
      p.shift = shift;
      const ModalBasis basis =
        ModalSolver(p).solve(component.stiffness_matrix(),
                             component.mass_matrix(),
                             "beam");
      // dsygv's eigenvalues carry an absolute error of about
      // eps * lambda_max, i.e. a relative one of 1e-9..1e-8 for lambda_1 here;
      // the modes lie at least 5 % apart, so 1e-7 leaves no room for a
      // missing or spurious one.
      ASSERT_EQ(basis.size(), 9u);
      for (unsigned int j = 0; j < 9; ++j)
        EXPECT_NEAR(basis.eigenvalues[j] / dense[j], 1., 1e-7) << "mode " << j;
    }
}

TEST(ModalSolver, ModesAreMassNormalisedWithSmallResiduals)
{
  const Scene      scene = Scene::read(source_dir + "/prm/overlap.prm");
  const Component  component(scene.components[0], scene.plane_model);
  const ModalBasis basis =
    ModalSolver(ModalParameters())
      .solve(component.stiffness_matrix(), component.mass_matrix(), "P1");
  ASSERT_EQ(basis.size(), 9u);
  for (unsigned int j = 0; j < basis.size(); ++j)
    {
      EXPECT_NEAR(component.mass_matrix().matrix_norm_square(basis.modes[j]),
                  1.,
                  1e-12);
      EXPECT_LT(basis.residuals[j], 1e-8) << "mode " << j;
      // clamped DoFs do not move
      for (unsigned int i = 0; i < component.n_dofs(); ++i)
        {
          if (component.is_constrained(i))
            {
              ASSERT_EQ(basis.modes[j][i], 0.);
            }
        }
    }
  // The residual is recomputed independently here.
  const auto r = relative_residuals(component.stiffness_matrix(),
                                    component.mass_matrix(),
                                    basis.eigenvalues,
                                    basis.modes);
  for (unsigned int j = 0; j < basis.size(); ++j)
    EXPECT_EQ(r[j], basis.residuals[j]);
}

TEST(ModalSolver, CutoffFrequencyReturnsEveryModeBelowIt)
{
  const Scene     scene = Scene::read(source_dir + "/prm/overlap.prm");
  const Component component(scene.components[0], scene.plane_model);
  ModalParameters p;
  p.n_modes              = 2; // ignored: the cutoff rules
  p.cutoff_frequency     = 25000;
  const ModalBasis basis = ModalSolver(p).solve(component.stiffness_matrix(),
                                                component.mass_matrix(),
                                                "P1");
  // 8 bending modes (the 8th at about 23 kHz) and 2 axial ones.
  ASSERT_EQ(basis.size(), 10u);
  EXPECT_LT(basis.frequencies().back(), 25000.);
  EXPECT_GT(basis.frequencies().back(), 22000.);
}

// ARPACK out of iterations: a message naming the key, never the
// unconverged Ritz pairs (deal.II says so by a debug-mode assertion only).
TEST(ModalSolver, RunningOutOfIterationsNamesTheKey)
{
  const Scene     scene = Scene::read(source_dir + "/prm/overlap.prm");
  const Component component(scene.components[0], scene.plane_model);
  ModalParameters p;
  p.n_modes        = 20;
  p.max_iterations = 1;
  std::string message;
  try
    {
      ModalSolver(p).solve(component.stiffness_matrix(),
                           component.mass_matrix(),
                           "P1");
    }
  catch (const dealii::ExceptionBase &e)
    {
      message = Input::message_of(e);
    }
  EXPECT_NE(message.find("key 'max iterations' of subsection Modal analysis"),
            std::string::npos)
    << message;
  // The default limit converges (and so does an explicit one).
  p.max_iterations       = 300;
  const ModalBasis basis = ModalSolver(p).solve(component.stiffness_matrix(),
                                                component.mass_matrix(),
                                                "P1");
  EXPECT_EQ(basis.size(), 20u);
  for (const double r : basis.residuals)
    EXPECT_LT(r, 1e-8);
}

TEST(ModalSolver, SingularStiffnessGivesAClearMessage)
{
  const Scene     scene = three_zone_scene("");
  const Component component(scene.components[0], scene.plane_model);
  try
    {
      ModalSolver(ModalParameters())
        .solve(component.stiffness_matrix(), component.mass_matrix(), "beam");
      FAIL() << "an unclamped body at shift 0 must be refused";
    }
  catch (const dealii::ExceptionBase &e)
    {
      EXPECT_NE(Input::message_of(e).find(
                  "beam: K - sigma M is singular at the shift sigma = 0"),
                std::string::npos)
        << Input::message_of(e);
    }
}

// ----------------------------------------------------------------------------
// The sparse Cholesky factorisation (CHOLMOD) against UMFPACK's LU
// ----------------------------------------------------------------------------

TEST(SparseCholesky, TrailingBlockIsTheInverseRestrictedToTheLastDofs)
{
  // The clamped cantilever (Q2, 25 x 1 cells); the DoFs ordered last are
  // those of the top face's vertices and one interior column, in an order
  // of their own.
  const Scene     scene = three_zone_scene("left");
  const Component component(scene.components[0], scene.plane_model, 1);
  const auto     &K = component.stiffness_matrix();
  std::vector<dealii::types::global_dof_index> last;
  for (double x = 0.02; x < 0.2; x += 0.02)
    for (const auto dof : component.vertex_dofs(dealii::Point<2>(x, 0.008)))
      last.push_back(dof);
  for (const auto dof : component.vertex_dofs(dealii::Point<2>(0.2, 0)))
    last.push_back(dof);
  std::reverse(last.begin(), last.end());

  SparseCholesky cholesky;
  cholesky.factorize(K, last, "beam");
  auto trailing = cholesky.trailing_dofs();
  ASSERT_EQ(trailing.size(), last.size());
  EXPECT_TRUE(
    std::is_permutation(trailing.begin(), trailing.end(), last.begin()));

  SparseDirectSolver lu;
  lu.factorize(K);
  const dealii::FullMatrix<double> G       = cholesky.trailing_inverse();
  double                           largest = 0, difference = 0;
  for (unsigned int j = 0; j < trailing.size(); ++j)
    {
      dealii::Vector<double> e(K.m());
      e[trailing[j]] = 1;
      lu.solve(e);
      for (unsigned int i = 0; i < trailing.size(); ++i)
        {
          largest    = std::max(largest, std::abs(e[trailing[i]]));
          difference = std::max(difference, std::abs(G(i, j) - e[trailing[i]]));
        }
    }
  // Both factorisations are backward stable; their forward errors are
  // bounded by cond(K) eps, about 1e-9 for this thin beam.
  EXPECT_GT(largest, 0.);
  EXPECT_LT(difference, 1e-8 * largest);

  // A solve of a whole load vector: a residual at round-off (backward
  // error), and the LU solution to the same forward accuracy.
  const dealii::Vector<double> f = component.load_vector();
  dealii::Vector<double>       u = f, v = f, r(f.size());
  cholesky.solve(u);
  K.vmult(r, u);
  r -= f;
  EXPECT_LT(r.linfty_norm(),
            1e-12 * (K.linfty_norm() * u.linfty_norm() + f.linfty_norm()));
  lu.solve(v);
  v -= u;
  EXPECT_LT(v.linfty_norm(), 1e-8 * u.linfty_norm());
}

// RowUpdatedLU against a new LAPACK factorisation of the matrix with its
// rows replaced (an independent solve): the Woodbury update must solve it
// to round-off, whether the rows are new, asked before (their columns
// kept) or none; a replacement that makes the matrix singular is refused.
TEST(RowUpdatedLU, SolvesLikeAFactorisationOfTheReplacedMatrix)
{
  const unsigned int  N = 60;
  std::vector<double> A0(N * N), A1(N * N);
  // A non-symmetric matrix with a dominant diagonal, and another one whose
  // rows replace some of it (as a tangential equation replaces a row of W).
  for (unsigned int j = 0; j < N; ++j)
    for (unsigned int i = 0; i < N; ++i)
      {
        A0[j * N + i] = std::sin(1. + i + 7. * j) + (i == j ? N : 0.);
        A1[j * N + i] = std::cos(2. + 3. * i + j) + (i == j ? 2. : 0.);
      }
  dealii::Vector<double> b(N);
  for (unsigned int i = 0; i < N; ++i)
    b[i] = 1. + std::sin(0.3 * i);
  // The matrix A0 with rows R from A1, solved by LAPACK afresh.
  const auto reference = [&](const std::vector<unsigned int> &R) {
    dealii::LAPACKFullMatrix<double> M(N, N);
    for (unsigned int i = 0; i < N; ++i)
      for (unsigned int j = 0; j < N; ++j)
        M(i, j) = A0[j * N + i];
    for (const unsigned int i : R)
      for (unsigned int j = 0; j < N; ++j)
        M(i, j) = A1[j * N + i];
    M.compute_lu_factorization();
    dealii::Vector<double> x = b;
    M.solve(x);
    return x;
  };

  RowUpdatedLU lu;
  ASSERT_TRUE(lu.factorise(A0, N, 1e-13));
  dealii::Vector<double> x(N);
  for (const std::vector<unsigned int> &R :
       {std::vector<unsigned int>{3, 17, 41},
        std::vector<unsigned int>{17, 5, 59, 0}, // 17 asked before
        std::vector<unsigned int>{},
        std::vector<unsigned int>{41}})
    {
      ASSERT_TRUE(lu.replace_rows(A1, R));
      EXPECT_EQ(lu.replaced_rows(), R);
      lu.vmult(x, b);
      dealii::Vector<double> error = reference(R);
      error -= x;
      EXPECT_LT(error.linfty_norm(), 1e-12 * x.linfty_norm())
        << R.size() << " rows replaced";
    }
  // One back-substitution per row ever asked: 3, 17, 41, 5, 59, 0.
  EXPECT_EQ(lu.n_cached_columns(), 6u);

  // Row 8 replaced by row 9 of A0 itself: singular, refused, and the
  // factors solve A0 again.
  std::vector<double> twin = A0;
  for (unsigned int j = 0; j < N; ++j)
    twin[j * N + 8] = A0[j * N + 9];
  EXPECT_FALSE(lu.replace_rows(twin, {8}));
  EXPECT_TRUE(lu.replaced_rows().empty());
  lu.vmult(x, b);
  dealii::Vector<double> error = reference({});
  error -= x;
  EXPECT_LT(error.linfty_norm(), 1e-12 * x.linfty_norm());
  // And a singular matrix is not factorised.
  RowUpdatedLU singular;
  EXPECT_FALSE(singular.factorise(twin, N, 1e-13));
  EXPECT_TRUE(singular.empty());

  // A copy (a load step adopting another's factors) shares A0's factors
  // and their kept columns: it solves with rows of its own replaced, and
  // the original made anew (here: of A1) leaves the copy's A0 as it was.
  RowUpdatedLU copy = lu;
  EXPECT_EQ(copy.n_cached_columns(), 7u); // and row 8's

  ASSERT_TRUE(lu.factorise(A1, N, 1e-13));
  EXPECT_EQ(lu.n_cached_columns(), 0u);
  ASSERT_TRUE(copy.replace_rows(A1, {59, 2}));
  EXPECT_EQ(copy.n_cached_columns(), 8u);
  copy.vmult(x, b);
  error = reference({59, 2});
  error -= x;
  EXPECT_LT(error.linfty_norm(), 1e-12 * x.linfty_norm());
}

// The condition estimate that decides whether factors are kept, against
// LAPACK's own dgecon on getrf's factors: the same estimator with other
// triangular solves, so the same value to round-off, on matrices from well
// conditioned to nearly singular (graded columns).
extern "C" void
dgecon_(const char                    *norm,
        const dealii::types::blas_int *n,
        const double                  *a,
        const dealii::types::blas_int *lda,
        const double                  *anorm,
        double                        *rcond,
        double                        *work,
        dealii::types::blas_int       *iwork,
        dealii::types::blas_int       *info);

TEST(RowUpdatedLU, EstimatesTheConditionAsLapackDoes)
{
  for (const unsigned int N : {1u, 7u, 60u, 300u})
    for (const double grading : {0., 4., 12., 17.})
      {
        std::vector<double> A(std::size_t(N) * N);
        double              norm = 0;
        for (unsigned int j = 0; j < N; ++j)
          {
            double column = 0;
            for (unsigned int i = 0; i < N; ++i)
              {
                double &a = A[std::size_t(j) * N + i];
                a         = (std::sin(1. + i + 7. * j) + (i == j ? 2. : 0.)) *
                    std::pow(10., -grading * j / std::max(1u, N - 1));
                column += std::abs(a);
              }
            norm = std::max(norm, column);
          }
        std::vector<double>                  lu = A, work(4 * N);
        const dealii::types::blas_int        n  = N;
        std::vector<dealii::types::blas_int> pivots(N), iwork(N);
        dealii::types::blas_int              info     = 0;
        double                               expected = 0;
        dealii::getrf(&n, &n, lu.data(), &n, pivots.data(), &info);
        ASSERT_EQ(info, 0);
        dgecon_("1",
                &n,
                lu.data(),
                &n,
                &norm,
                &expected,
                work.data(),
                iwork.data(),
                &info);
        ASSERT_EQ(info, 0);
        RowUpdatedLU factors;
        factors.factorise(A, N, 0.);
        EXPECT_NEAR(factors.rcond(), expected, 1e-8 * expected)
          << N << " unknowns, columns graded over 1e-" << grading;
        // The threshold refuses the nearly singular ones.
        EXPECT_EQ(RowUpdatedLU().factorise(A, N, 1e-13), expected >= 1e-13)
          << N << " unknowns, columns graded over 1e-" << grading;
      }
}

// A body refactorised at new zone moduli keeps its pattern: the second
// factorisation copies the symbolic analysis of the first (counted) and must
// give the same bits as a factorisation analysed afresh; a pattern with
// other DoFs ordered last gets an analysis of its own (its trailing DoFs are
// those). The multi-column solve agrees with single solves to round-off,
// over several of its calls of CHOLMOD.
TEST(SparseCholesky, SharesTheAnalysisOfOnePatternAndSolvesManyColumns)
{
  const Scene scene = three_zone_scene("left");
  Component   component(scene.components[0], scene.plane_model, 1);
  std::vector<dealii::types::global_dof_index> last, other;
  for (const auto dof : component.vertex_dofs(dealii::Point<2>(0.1, 0.008)))
    last.push_back(dof);
  for (const auto dof : component.vertex_dofs(dealii::Point<2>(0.2, 0.008)))
    other.push_back(dof);
  const std::vector<double> moduli  = component.zone_moduli();
  std::vector<double>       changed = moduli;
  changed[1] *= 1.3;
  changed[2] *= 0.7;
  const std::vector<double> densities = component.zone_densities();

  const unsigned long shared = SparseCholesky::n_shared_analyses();
  SparseCholesky      nominal, again, fresh, elsewhere;
  nominal.factorize(component.stiffness_matrix(), last, "beam");
  component.set_zone_materials(changed, densities);
  const dealii::SparseMatrix<double> &K = component.stiffness_matrix();
  again.factorize(K, last, "beam");
  EXPECT_EQ(SparseCholesky::n_shared_analyses(), shared + 1);
  EXPECT_EQ(again.trailing_dofs(), nominal.trailing_dofs());

  // Two other patterns push the first out of the cache (it keeps two).
  elsewhere.factorize(K, other, "beam");
  EXPECT_EQ(SparseCholesky::n_shared_analyses(), shared + 1);
  std::vector<dealii::types::global_dof_index> trailing =
    elsewhere.trailing_dofs();
  std::sort(trailing.begin(), trailing.end());
  std::sort(other.begin(), other.end());
  EXPECT_EQ(trailing, other);
  {
    SparseCholesky plain;
    plain.factorize(K, {}, "beam");
  }
  fresh.factorize(K, last, "beam");
  EXPECT_EQ(SparseCholesky::n_shared_analyses(), shared + 1);

  const unsigned int     n = K.m();
  dealii::Vector<double> f = component.load_vector(), u = f, v = f;
  again.solve(u);
  fresh.solve(v);
  EXPECT_EQ(u, v); // the same analysis, the same numeric factorisation
  EXPECT_EQ(again.trailing_inverse(), fresh.trailing_inverse());
  SparseDirectSolver lu;
  lu.factorize(K);
  dealii::Vector<double> w = f;
  lu.solve(w);
  w -= u;
  EXPECT_LT(w.linfty_norm(), 1e-8 * u.linfty_norm());

  // 131 columns at once: CHOLMOD solves up to 64 a call (its workspace
  // stays that small), so two full blocks and a remainder of three.
  const unsigned int  b = 131;
  std::vector<double> columns(std::size_t(b) * n);
  for (unsigned int j = 0; j < b; ++j)
    for (unsigned int i = 0; i < n; ++i)
      columns[std::size_t(j) * n + i] = std::sin(0.3 * (j + 1) * i);
  std::vector<double> single = columns;
  again.solve(columns.data(), b);
  for (unsigned int j = 0; j < b; ++j)
    {
      dealii::Vector<double> x(single.begin() + std::size_t(j) * n,
                               single.begin() + std::size_t(j + 1) * n);
      again.solve(x);
      double difference = 0;
      for (unsigned int i = 0; i < n; ++i)
        difference = std::max(difference,
                              std::abs(columns[std::size_t(j) * n + i] - x[i]));
      // (blocks of columns take other BLAS paths than one column: round-off)
      EXPECT_LE(difference, 1e-12 * x.linfty_norm()) << "column " << j;
    }
}

TEST(SparseCholesky, RefusesAnUnsupportedBodyNamingIt)
{
  const Scene     scene = three_zone_scene("");
  const Component component(scene.components[0], scene.plane_model);
  try
    {
      SparseCholesky cholesky;
      cholesky.factorize(component.stiffness_matrix(),
                         {},
                         "Component beam: the stiffness matrix");
      FAIL() << "an unclamped body must be refused";
    }
  catch (const dealii::ExceptionBase &e)
    {
      EXPECT_NE(Input::message_of(e).find(
                  "Component beam: the stiffness matrix is not positive "
                  "definite"),
                std::string::npos)
        << Input::message_of(e);
    }
}

TEST(ModalBasis, ClustersGroupCloseEigenvalues)
{
  ModalBasis basis;
  basis.eigenvalues = {1.0, 2.0, 2.0 + 1e-9, 3.0, 3.0 + 2e-3};
  const auto groups = basis.clusters(1e-6);
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_EQ(groups[1], (std::vector<unsigned int>{1, 2}));
  EXPECT_EQ(basis.clusters(1e-3).size(), 3u);
}


// ----------------------------------------------------------------------------
// Output
// ----------------------------------------------------------------------------

TEST(Output, FilesAppearOnlyWhenWrittenAndWhole)
{
  namespace fs         = std::filesystem;
  const fs::path where = fs::temp_directory_path() / "fuzzycontact-output-test";
  fs::remove_all(where);
  OutputFiles files(where.string());
  files.add("a.txt", "alpha\n");
  files.add("sub/b.txt", std::string(1 << 20, 'x'));
  EXPECT_FALSE(fs::exists(where)); // nothing before write_all()
  files.write_all();
  std::ifstream a(where / "a.txt");
  std::string   line;
  std::getline(a, line);
  EXPECT_EQ(line, "alpha");
  EXPECT_EQ(fs::file_size(where / "sub" / "b.txt"), 1u << 20);
  for (const auto &entry : fs::recursive_directory_iterator(where))
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos);
  fs::remove_all(where);
}


// ----------------------------------------------------------------------------
// Progress lines
// ----------------------------------------------------------------------------

// The remaining time is the elapsed time per step times the steps left;
// "quiet" prints nothing, whatever standard error is.
TEST(Progress, LineEstimatesTheRemainingTimeAndQuietIsSilent)
{
  EXPECT_EQ(ProgressLines::line("samples", 160, 640, 2.0),
            "  ... samples: 160/640 (25 %), 2.0 s elapsed, about 6.0 s left");
  EXPECT_EQ(ProgressLines::line("samples", 640, 640, 12.4),
            "  ... samples: 640/640 (100 %), 12 s elapsed");
  // the optimisation's lines carry the evaluations made so far
  EXPECT_EQ(ProgressLines::line("bounds", 22, 88, 1.0, "1912 evaluations"),
            "  ... bounds: 22/88 (25 %), 1912 evaluations, 1.0 s elapsed, "
            "about 3.0 s left");
  ProgressLines::set_verbosity(ProgressLines::Verbosity::quiet);
  EXPECT_FALSE(ProgressLines::enabled());
  ProgressLines::set_verbosity(ProgressLines::Verbosity::progress);
  EXPECT_TRUE(ProgressLines::enabled());
  ProgressLines::set_verbosity(ProgressLines::Verbosity::automatic);
}


// ----------------------------------------------------------------------------
// Components from mesh files
// ----------------------------------------------------------------------------

namespace
{
  namespace fs = std::filesystem;

  // A structured nx x ny mesh of the rectangle [x0, x1] x [y0, y1] in Gmsh's
  // ASCII format 2.2: physical curves left, right, bottom, top (tags 1-4),
  // physical surface "body" (tag 7). With @p triangle, the first cell is
  // two triangles; with @p inverted, its corners are listed crossed.
  std::string
  rectangle_msh(const double   x0,
                const double   x1,
                const double   y0,
                const double   y1,
                const unsigned nx,
                const unsigned ny,
                const bool     triangle = false,
                const bool     inverted = false)
  {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n"
      << "1 1 \"left\"\n1 2 \"right\"\n1 3 \"bottom\"\n1 4 \"top\"\n"
      << "2 7 \"body\"\n$EndPhysicalNames\n$Nodes\n"
      << (nx + 1) * (ny + 1) << "\n";
    const auto id = [&](unsigned i, unsigned j) {
      return j * (nx + 1) + i + 1;
    };
    for (unsigned j = 0; j <= ny; ++j)
      for (unsigned i = 0; i <= nx; ++i)
        s << id(i, j) << " " << x0 + (x1 - x0) * i / nx << " "
          << y0 + (y1 - y0) * j / ny << " 0\n";
    s << "$EndNodes\n$Elements\n";
    std::ostringstream e;
    unsigned           n = 0;
    for (unsigned j = 0; j < ny; ++j)
      {
        e << ++n << " 1 2 1 1 " << id(0, j) << " " << id(0, j + 1) << "\n";
        e << ++n << " 1 2 2 2 " << id(nx, j) << " " << id(nx, j + 1) << "\n";
      }
    for (unsigned i = 0; i < nx; ++i)
      {
        e << ++n << " 1 2 3 3 " << id(i, 0) << " " << id(i + 1, 0) << "\n";
        e << ++n << " 1 2 4 4 " << id(i, ny) << " " << id(i + 1, ny) << "\n";
      }
    for (unsigned j = 0; j < ny; ++j)
      for (unsigned i = 0; i < nx; ++i)
        if (triangle && i == 0 && j == 0)
          {
            e << ++n << " 2 2 7 5 " << id(0, 0) << " " << id(1, 0) << " "
              << id(1, 1) << "\n";
            e << ++n << " 2 2 7 5 " << id(0, 0) << " " << id(1, 1) << " "
              << id(0, 1) << "\n";
          }
        else if (inverted && i == 0 && j == 0)
          e << ++n << " 3 2 7 5 " << id(0, 0) << " " << id(1, 0) << " "
            << id(0, 1) << " " << id(1, 1) << "\n";
        else
          e << ++n << " 3 2 7 5 " << id(i, j) << " " << id(i + 1, j) << " "
            << id(i + 1, j + 1) << " " << id(i, j + 1) << "\n";
    s << n << "\n" << e.str() << "$EndElements\n";
    return s.str();
  }

  // Two stacked cantilevers (the overlap scene's P1 on P2, clamped at
  // opposite ends), as rectangles or as mesh files of the same cells.
  std::string
  stacked_scene(const bool mesh_files, const std::string &extra = "")
  {
    const auto geometry = [&](const std::string &file,
                              const std::string &lower,
                              const std::string &upper) {
      return mesh_files ? "  set mesh file = " + file + "\n"
                        : "  set lower left corner = " + lower +
                            "\n  set upper right corner = " + upper +
                            "\n  set subdivisions = 8, 2\n";
    };
    return "subsection Scene\n  set name = meshes\n  set components = P1, "
           "P2\n  set contact pairs = interface\nend\n"
           "subsection Component P1\n" +
           geometry("p1.msh", "0, 0.01", "0.4, 0.03") +
           "  set clamped faces = left\n  set loads = tip\n"
           "  subsection Load tip\n    set face = right\n"
           "    set total force = 2e4\n    set direction = 0, -1\n  end\n"
           "end\nsubsection Component P2\n" +
           geometry("p2.msh", "0.1, -0.01", "0.5, 0.01") +
           "  set clamped faces = right\n" + extra +
           "end\nsubsection Contact interface\n"
           "  set slave component = P1\n  set slave face = bottom\n"
           "  set master component = P2\n  set master face = top\n"
           "  set friction coefficient = 0.3\nend\n";
  }

  struct MeshFolder
  {
    fs::path path;
    MeshFolder()
        : path(fs::temp_directory_path() /
               ("fuzzycontact-meshes-" + std::to_string(::getpid())))
    {
      fs::create_directories(path);
      write("p1.msh", rectangle_msh(0, 0.4, 0.01, 0.03, 8, 2));
      write("p2.msh", rectangle_msh(0.1, 0.5, -0.01, 0.01, 8, 2));
    }
    ~MeshFolder()
    {
      fs::remove_all(path);
    }
    void
    write(const std::string &name, const std::string &text) const
    {
      std::ofstream(path / name) << text;
    }
    Scene
    read(const std::string &text) const
    {
      write("scene.prm", text);
      return Scene::read((path / "scene.prm").string());
    }
  };

  std::string
  message_of_reading(const MeshFolder &folder, const std::string &text)
  {
    try
      {
        folder.read(text);
      }
    catch (const dealii::ExceptionBase &e)
      {
        return Input::message_of(e);
      }
    return "";
  }
} // namespace


// The same two cantilevers built as rectangles and read from Gmsh files of
// the same cells give the same contact answer (round-off: the DoFs are
// numbered differently): the reader, the names and the contact geometry
// on mesh files agree with the rectangles.
TEST(MeshFiles, ReadRectanglesSolveLikeGeneratedOnes)
{
  const MeshFolder folder;
  const Scene      generated = Scene::read_from_string(stacked_scene(false));
  const Scene      read      = folder.read(stacked_scene(true));
  EXPECT_FALSE(read.components[0].is_rectangle());
  EXPECT_NEAR(read.components[0].upper_right[0], 0.4, 1e-15);
  double       answers[2][2];
  unsigned int nodes[2];
  for (const unsigned r : {0u, 1u})
    {
      const Scene *scene[2] = {&generated, &read};
      for (unsigned k = 0; k < 2; ++k)
        {
          ContactScene   bodies(*scene[k], r);
          FullOrderModel full(bodies, ObservedDofs(2));
          full.set_state(SceneState(*scene[k]));
          const ContactSolution s = full.solve();
          answers[k][0]           = s.normal_force;
          answers[k][1]           = s.tangential_force;
          nodes[k]                = bodies.interface().n_nodes();
        }
      EXPECT_EQ(nodes[1], nodes[0]);
      EXPECT_GT(answers[0][0], 1e3);
      EXPECT_NEAR(answers[1][0], answers[0][0], 1e-10 * answers[0][0]);
      EXPECT_NEAR(answers[1][1], answers[0][1], 1e-10 * answers[0][0]);
    }
}


namespace
{
  // The stacked scene with P2 read from the Abaqus file @p file (of the
  // same cells as the rectangle), with @p extra for P2.
  std::string
  abaqus_scene(const std::string &file, const std::string &extra = "")
  {
    std::string       text = stacked_scene(false, extra);
    const std::string rectangle =
      "  set lower left corner = 0.1, -0.01\n  set upper right corner = 0.5, "
      "0.01\n  set subdivisions = 8, 2\n";
    text.replace(text.find(rectangle),
                 rectangle.size(),
                 "  set mesh file = " + file + "\n");
    return text;
  }

  // P2 in two zones, steel (x < 0.3) and a softer bronze; with @p ranges
  // for a rectangle, without for a mesh file (its element sets).
  std::string
  two_zones(const bool ranges)
  {
    return std::string("  set zones = steel, bronze\n  subsection Zone "
                       "steel\n") +
           (ranges ? "    set x range = 0.1, 0.3\n" : "") +
           "    set E = 210e9\n  end\n  subsection Zone bronze\n" +
           (ranges ? "    set x range = 0.3, 0.5\n" : "") +
           "    set E = 110e9\n  end\n";
  }

  // Normal and tangential contact force of the full-order solve.
  std::array<double, 2>
  contact_forces(const Scene &scene, const unsigned int refinements)
  {
    ContactScene   bodies(scene, refinements);
    FullOrderModel full(bodies, ObservedDofs(2));
    full.set_state(SceneState(scene));
    const ContactSolution s = full.solve();
    return {{s.normal_force, s.tangential_force}};
  }
} // namespace


// P2 read from tests/meshes/stacked-p2.inp (an Abaqus file in the style of
// Abaqus/CAE: surfaces by element sets and by elements, internal sets,
// sections, materials and a step, all but the mesh and the names ignored)
// solves like the generated rectangle of the same cells, with one zone and
// with the file's element sets steel and bronze as zones of different
// moduli against the rectangle's x ranges. deal.II's reader rounds the
// coordinates to 9 digits; they are restored to the file's.
TEST(MeshFiles, AbaqusBlockSolvesLikeTheGeneratedRectangle)
{
  const std::string inp      = source_dir + "/tests/meshes/stacked-p2.inp";
  double            one_zone = 0;
  {
    const MeshFolder folder;
    folder.write("digits.inp",
                 replace(Input::read_text_file(inp),
                         "14, 0.30000000000000004, 0\n",
                         "14, 0.30000000123456789, 9.8765432109876e-10\n"));
    const MeshFileInfo info =
      read_mesh_file((folder.path / "digits.inp").string(), 1, "test");
    Triangulation<2> triangulation;
    create_mesh(info, 1, triangulation, "test");
    const Point<2> node(0.30000000123456789, 9.8765432109876e-10);
    double         nearest = 1;
    for (const Point<2> &v : triangulation.get_vertices())
      nearest = std::min(nearest, v.distance(node));
    EXPECT_LT(nearest, 1e-17);
  }
  for (const bool zones : {false, true})
    {
      const Scene generated =
        Scene::read_from_string(stacked_scene(false, two_zones(true)));
      const Scene read =
        Scene::read_from_string(abaqus_scene(inp, two_zones(false)));
      const Scene generated_one = Scene::read_from_string(stacked_scene(false));
      const Scene read_one      = Scene::read_from_string(abaqus_scene(inp));
      const ComponentDescription &p2 = (zones ? read : read_one).components[1];
      EXPECT_FALSE(p2.is_rectangle());
      EXPECT_EQ(p2.mesh.face_names(), "bottom, left, right, top");
      EXPECT_EQ(p2.mesh.zone_names(), "bronze, steel");
      EXPECT_NEAR(p2.upper_right[0], 0.5, 1e-15);
      EXPECT_NEAR(p2.lower_left[1], -0.01, 1e-15);
      for (const unsigned int r : {0u, 1u})
        {
          const auto a = contact_forces(zones ? generated : generated_one, r);
          const auto b = contact_forces(zones ? read : read_one, r);
          EXPECT_GT(a[0], 1e3);
          EXPECT_NEAR(b[0], a[0], 1e-10 * a[0]) << "refinements " << r;
          EXPECT_NEAR(b[1], a[1], 1e-10 * a[0]) << "refinements " << r;
          if (!zones && r == 0)
            one_zone = a[0];
          else if (r == 0) // the softer bronze changes the answer
            {
              EXPECT_GT(std::abs(a[0] - one_zone), 1e-3 * one_zone);
            }
        }
    }
}


// An Abaqus file's bad names and elements are refused naming the file and
// the key: an unknown surface or element set (listing those it has), a
// zone list that misses a set, triangles, elements not numbered 1, 2, ...,
// element sets that share an element, a missing file.
TEST(MeshFiles, BadAbaqusFilesAreRefusedWithTheFileAndTheKey)
{
  const MeshFolder  folder;
  const std::string good =
    Input::read_text_file(source_dir + "/tests/meshes/stacked-p2.inp");
  folder.write("p2.inp", good);
  const auto message = [&](const std::string &text) {
    return message_of_reading(folder, text);
  };
  std::string m = message(replace(abaqus_scene("p2.inp"),
                                  "set clamped faces = right",
                                  "set clamped faces = rim"));
  EXPECT_NE(m.find("Component P2: clamped faces: <"), std::string::npos) << m;
  EXPECT_NE(m.find("p2.inp> has no surface called <rim>; it has: bottom, "
                   "left, right, top."),
            std::string::npos)
    << m;

  m = message(abaqus_scene(
    "p2.inp",
    replace(replace(two_zones(false), "bronze", "brass"), "bronze", "brass")));
  EXPECT_NE(m.find("Component P2, zone brass: <"), std::string::npos) << m;
  EXPECT_NE(m.find("has no element set called <brass>; it has: bronze, "
                   "steel."),
            std::string::npos)
    << m;

  const std::string steel_only =
    "  set zones = steel\n  subsection Zone steel\n  end\n";
  try
    {
      const Scene  scene = folder.read(abaqus_scene("p2.inp", steel_only));
      ContactScene bodies(scene, 0);
      ADD_FAILURE() << "a zone list without bronze was accepted";
    }
  catch (const dealii::ExceptionBase &e)
    {
      m = Input::message_of(e);
      EXPECT_NE(m.find("(0.325, -0.005) of <"), std::string::npos) << m;
      EXPECT_NE(m.find("lies in no zone the component lists (element set "
                       "id 2, 0: in no element set); list every element set "
                       "of the file in 'zones' (it has: bronze, steel)"),
                std::string::npos)
        << m;
    }

  const auto with_file = [&](const std::string &from, const std::string &to) {
    folder.write("bad.inp", replace(good, from, to));
    return message(abaqus_scene("bad.inp"));
  };
  m = with_file("1, 1, 2, 11, 10\n", "1, 1, 2, 11\n");
  EXPECT_NE(m.find("Component P2: mesh file: <"), std::string::npos) << m;
  EXPECT_NE(m.find("bad.inp>: element 1 is a triangle"), std::string::npos)
    << m;
  EXPECT_NE(m.find("Quad"), std::string::npos) << m;

  m = with_file("1, 1, 2, 11, 10\n", "17, 1, 2, 11, 10\n");
  EXPECT_NE(m.find("element 17 should be numbered 1"), std::string::npos) << m;

  m = with_file("1, 2, 3, 4, 9,", "1, 2, 3, 4, 5, 9,");
  EXPECT_NE(m.find("the element sets <steel> and <bronze> share element 5"),
            std::string::npos)
    << m;

  m = message(abaqus_scene("nowhere.inp"));
  EXPECT_NE(m.find("Component P2: mesh file: <"), std::string::npos) << m;
  EXPECT_NE(m.find("nowhere.inp> is not a file that exists"), std::string::npos)
    << m;
}


// Unknown names, triangles, inverted cells, a missing file and zones the
// file does not have are refused, naming the file and the key.
TEST(MeshFiles, BadMeshesAreRefusedWithTheFileAndTheKey)
{
  const MeshFolder folder;
  std::string      text = stacked_scene(true);
  const auto       with = [&](const std::string &from, const std::string &to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  std::string m = message_of_reading(folder,
                                     with("set clamped faces = right",
                                          "set clamped faces = rim"));
  EXPECT_NE(m.find("Component P2: clamped faces: <"), std::string::npos) << m;
  EXPECT_NE(m.find("p2.msh> has no physical curve called <rim>; it has: "
                   "bottom, left, right, top."),
            std::string::npos)
    << m;

  m = message_of_reading(folder,
                         with("set slave face = bottom",
                              "set slave face = base"));
  EXPECT_NE(m.find("Contact interface: slave face: <"), std::string::npos) << m;

  folder.write("tri.msh", rectangle_msh(0.1, 0.5, -0.01, 0.01, 8, 2, true));
  m = message_of_reading(folder, with("p2.msh", "tri.msh"));
  EXPECT_NE(m.find("tri.msh>: the mesh has triangles"), std::string::npos) << m;
  EXPECT_NE(m.find("Mesh.RecombineAll"), std::string::npos) << m;

  folder.write("bad.msh",
               rectangle_msh(0.1, 0.5, -0.01, 0.01, 8, 2, false, true));
  m = message_of_reading(folder, with("p2.msh", "bad.msh"));
  EXPECT_NE(m.find("bad.msh>"), std::string::npos) << m;
  EXPECT_NE(m.find("inverted or degenerate"), std::string::npos) << m;

  m = message_of_reading(folder, with("p2.msh", "nowhere.msh"));
  EXPECT_NE(m.find("Component P2: mesh file: <"), std::string::npos) << m;
  EXPECT_NE(m.find("nowhere.msh> is not a file that exists"), std::string::npos)
    << m;

  text = stacked_scene(true,
                       "  set zones = steel\n  subsection Zone steel\n  end\n");
  m    = message_of_reading(folder, text);
  EXPECT_NE(m.find("Component P2, zone steel: <"), std::string::npos) << m;
  EXPECT_NE(m.find("has no physical surface called <steel>; it has: body."),
            std::string::npos)
    << m;

  // P1's bottom face over P2's bottom face: the normals do not face.
  text = stacked_scene(true);
  try
    {
      const Scene scene =
        folder.read(with("set master face = top", "set master face = bottom"));
      ContactScene bodies(scene, 0);
      ADD_FAILURE() << "faces that cannot touch were accepted";
    }
  catch (const dealii::ExceptionBase &e)
    {
      EXPECT_NE(Input::message_of(e).find("cannot touch"), std::string::npos)
        << Input::message_of(e);
    }
}


// The roller's arc is exact: with the SphericalManifold and the mapping of
// degree 2, every node of the arc lies on the circle; and the full-order
// Hertz contact matches a = sqrt(4 P R / (pi E*)) within one slave-node
// spacing and p0 = 2 P / (pi a) within 2 % at the shipped mesh.
namespace
{
  // Solves a Hertz scene (a roller on a block, frictionless) by the
  // full-order model and checks the contact half-width to one slave-node
  // spacing and the peak pressure (averaged over three nodes) to 2 %
  // against Hertz's values for the computed contact force.
  ContactSolution
  expect_hertz(const Scene &scene, ContactScene &bodies)
  {
    const auto    &arc = scene.components[0].mesh.arcs.begin()->second;
    FullOrderModel full(bodies, ObservedDofs(2));
    full.set_state(SceneState(scene));
    const ContactSolution s = full.solve_with_fields();
    const auto &roller = scene.components[0], &block = scene.components[1];
    const HertzTheory::Cylinder hertz{
      arc.radius,
      HertzTheory::contact_modulus(roller.zones[0].youngs_modulus,
                                   roller.zones[0].poissons_ratio,
                                   block.zones[0].youngs_modulus,
                                   block.zones[0].poissons_ratio),
      s.normal_force / roller.thickness};
    const auto zone =
      HertzTheory::contact_zone(HertzTheory::profile(bodies.interface(),
                                                     s,
                                                     0,
                                                     Point<2>(0, 0),
                                                     roller.thickness));
    EXPECT_NEAR(zone.half_width, hertz.half_width(), zone.node_spacing);
    EXPECT_NEAR(zone.peak_pressure / hertz.peak_pressure(), 1., 0.02);
    // Frictionless: no tangential force; force balance of the nodal forces.
    EXPECT_NEAR(s.tangential_force, 0., 1e-10 * s.normal_force);

    // The stress in the block under the middle of the contact, from the
    // surface to 3a deep, against McEwen's closed form for the same P: the
    // largest von Mises stress and in-plane shear, and their depths (the
    // 61 points 0.05 a apart).
    const double a = hertz.half_width(), p0 = hertz.peak_pressure();
    const HertzTheory::SubsurfacePeaks peaks =
      HertzTheory::subsurface_peaks(hertz,
                                    bodies.component(1),
                                    s.displacements[1],
                                    Point<2>(0, 0),
                                    block.zones[0].youngs_modulus,
                                    block.zones[0].poissons_ratio);
    EXPECT_NEAR(peaks.fe_von_mises.value / peaks.von_mises.value, 1., 0.02);
    EXPECT_NEAR(peaks.fe_von_mises.depth, peaks.von_mises.depth, 0.1 * a);
    EXPECT_NEAR(peaks.fe_shear.value / peaks.shear.value, 1., 0.02);
    EXPECT_NEAR(peaks.fe_shear.depth, peaks.shear.depth, 0.1 * a);
    std::cout << "Hertz subsurface: von Mises " << peaks.fe_von_mises.value / p0
              << " p0 at " << peaks.fe_von_mises.depth / a << " a (closed form "
              << peaks.von_mises.value / p0 << " p0 at "
              << peaks.von_mises.depth / a << " a), shear "
              << peaks.fe_shear.value / p0 << " p0 at "
              << peaks.fe_shear.depth / a << " a (" << peaks.shear.value / p0
              << " p0 at " << peaks.shear.depth / a << " a)\n";
    return s;
  }
} // namespace

// Lame's thick cylinder under internal pressure p (plane strain, a quarter
// of the ring from a Gmsh geometry, its arcs exact, rollers on the two
// symmetry lines): sigma_rr = A - B / r^2, sigma_tt = A + B / r^2, sigma_zz
// = 2 nu A, A = p a^2 / (b^2 - a^2), B = p a^2 b^2 / (b^2 - a^2); the VTU
// files' stresses (StressPostprocessor) and their von Mises stress at every
// Gauss point within 0.5 % of p (16 x 32 Q2 cells; 0.8 % on 8 x 16).
TEST(Validation, LameThickCylinderStresses)
{
  const fs::path folder = fs::temp_directory_path() /
                          ("fuzzycontact-lame-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "ring.geo")
    << "a = 50; b = 100;\n"
       "Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0};\n"
       "Point(4) = {0, b, 0}; Point(5) = {0, a, 0};\n"
       "Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5};\n"
       "Circle(4) = {5, 1, 2};\n"
       "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
       "Transfinite Curve{1, 3} = 17; Transfinite Curve{2, 4} = 33;\n"
       "Transfinite Surface{1}; Recombine Surface{1};\n"
       "Physical Curve(\"bottom\") = {1}; Physical Curve(\"outer\") = {2};\n"
       "Physical Curve(\"left\") = {3}; Physical Curve(\"inner\") = {4};\n"
       "Physical Surface(\"steel\") = {1};\n";
  const Scene scene = Scene::read_from_string(
    "subsection Scene\n  set name = ring\n  set plane model = plane strain\n"
    "  set components = Ring\nend\n"
    "subsection Component Ring\n  set mesh file = " +
      (folder / "ring.geo").string() +
      "\n  set scale = 1e-3\n  set E = 210e9\n  set nu = 0.3\n"
      "  set supports = left-roller, bottom-roller\n"
      "  subsection Support left-roller\n    set face = left\n"
      "    set fixed components = x\n  end\n"
      "  subsection Support bottom-roller\n    set face = bottom\n"
      "    set fixed components = y\n  end\n"
      "  set loads = bore\n"
      "  subsection Load bore\n    set face = inner\n    set pressure = 1e8\n"
      "  end\nend\n",
    "ring.prm");
  fs::remove_all(folder);
  const double   E = 210e9, nu = 0.3, p = 1e8, a = 0.05, b = 0.1;
  const double   A = p * a * a / (b * b - a * a), B = A * b * b;
  Component      ring(scene.components[0], scene.plane_model);
  SparseCholesky K;
  K.factorize(ring.stiffness_matrix(), {}, "the ring");
  Vector<double> u = ring.load_vector();
  K.solve(u);

  double worst = 0, worst_mises = 0;
  for_each_gauss_point_stress(
    ring,
    u,
    {E},
    [&](const Point<2> &x, const Vector<double> &computed) {
      const double r2 = x.square(), c = x[0] * x[0] / r2, s = x[1] * x[1] / r2,
                   cs = x[0] * x[1] / r2;
      const double rr = A - B / r2, tt = A + B / r2, zz = 2 * nu * A;
      // The polar stresses in x, y.
      const std::array<double, 4> exact = {
        {rr * c + tt * s, rr * s + tt * c, (rr - tt) * cs, zz}};
      for (unsigned int i = 0; i < 4; ++i)
        worst = std::max(worst, std::abs(computed[i] - exact[i]));
      const double vm =
        std::sqrt(((rr - tt) * (rr - tt) + (tt - zz) * (tt - zz) +
                   (zz - rr) * (zz - rr)) /
                  2);
      worst_mises = std::max(worst_mises, std::abs(computed[4] - vm));
    });
  std::cout << "Lame: largest stress error " << worst / p << " p, von Mises "
            << worst_mises / p << " p\n";
  EXPECT_LT(worst, 5e-3 * p) << "largest stress error [Pa]";
  EXPECT_LT(worst_mises, 5e-3 * p) << "largest von Mises error [Pa]";
}

// McEwen's closed form under the middle of a Hertz line contact against
// the published figures (Johnson, Contact Mechanics, 4.3): the largest
// in-plane shear 0.300 p0 at 0.786 a for any nu; the largest von Mises
// stress 0.5575 p0 at 0.70 a for nu = 0.3 (plane strain).
TEST(Validation, HertzSubsurfaceStressIsThePublishedOne)
{
  const HertzTheory::Cylinder hertz{0.05, 58.6e9, 1.94e6};
  const double a = hertz.half_width(), p0 = hertz.peak_pressure();
  for (const double nu : {0.3, 0.45})
    {
      HertzTheory::Peak mises, shear;
      for (unsigned int k = 0; k <= 3000; ++k)
        {
          const double      z = 3 * a * k / 3000;
          const StressState s = hertz.stress_under_middle(z, nu);
          if (s.von_mises() > mises.value)
            mises = {s.von_mises(), z};
          const double t = (s.principal()[0] - s.principal()[1]) / 2;
          if (t > shear.value)
            shear = {t, z};
        }
      EXPECT_NEAR(shear.value / p0, 0.300, 5e-4) << "nu = " << nu;
      EXPECT_NEAR(shear.depth / a, 0.786, 1e-3) << "nu = " << nu;
      if (nu == 0.3)
        {
          EXPECT_NEAR(mises.value / p0, 0.5575, 5e-4);
          EXPECT_NEAR(mises.depth / a, 0.70, 0.01);
        }
    }
}

TEST(Validation, HertzRollerOnBlock)
{
  const Scene scene = Scene::read(source_dir + "/prm/hertz.prm");
  ASSERT_EQ(scene.components[0].mesh.arcs.size(), 1u);
  const auto &arc = scene.components[0].mesh.arcs.begin()->second;
  EXPECT_NEAR(arc.radius, 0.05, 1e-12);
  ContactScene bodies(scene, 0);
  for (const ContactNode &node : bodies.interface().nodes())
    EXPECT_NEAR(node.slave.position.distance(arc.centre),
                arc.radius,
                1e-12 * arc.radius);

  expect_hertz(scene, bodies);
}

// The same roller under load control (prm/hertz-load.prm): a force on its
// top face, which is held in x only, so that the contact alone holds the
// roller vertically and against rotation (its two free motions are solved
// with the contact forces). The contact force is the applied one by
// equilibrium, and Hertz's half-width and peak pressure follow as under
// displacement control.
TEST(Validation, HertzRollerOnBlockUnderLoadControl)
{
  const Scene  scene = Scene::read(source_dir + "/prm/hertz-load.prm");
  ContactScene bodies(scene, 0);
  ASSERT_EQ(bodies.component(0).free_motions().size(), 2u);
  const ContactSolution s = expect_hertz(scene, bodies);
  EXPECT_NEAR(s.normal_force,
              scene.components[0].loads[0].total_force,
              1e-10 * s.normal_force);
}


// A body its supports do not hold is held by contact alone: it is pinned
// for the solvers and its free motions are named. Without a contact pair
// nothing can hold it, and it is refused before any solve, naming the
// motion left free: a roller (x fixed) on P2's right face leaves it free to
// slide along y; without any support all three motions are free. With the
// pair, P2 under the roller carries no load and P1 only pushes it away: its
// position is not determined, which the solve says.
TEST(MeshFiles, AFloatingBodyNeedsAContactPairAndAPositionItsContactFixes)
{
  const auto message_of = [](const std::function<void()> &f) {
    try
      {
        f();
      }
    catch (const dealii::ExceptionBase &e)
      {
        return Input::message_of(e);
      }
    return std::string();
  };
  const auto message_of_building = [&](const std::string &text) {
    return message_of([&]() {
      const Scene  scene = Scene::read_from_string(text);
      ContactScene bodies(scene, 0);
    });
  };
  EXPECT_EQ(message_of_building(stacked_scene(false)), "");
  std::string roller = stacked_scene(false);
  roller.replace(roller.find("  set clamped faces = right\n"),
                 std::string("  set clamped faces = right\n").size(),
                 "  set supports = guide\n  subsection Support guide\n"
                 "    set face = right\n    set fixed components = x\n"
                 "  end\n");
  {
    const Scene  scene = Scene::read_from_string(roller);
    ContactScene bodies(scene, 0);
    EXPECT_EQ(bodies.component(1).free_rigid_motion(),
              "translation along (0, 1)");
    ASSERT_EQ(bodies.component(1).pinned_dofs().size(), 1u);
    EXPECT_TRUE(bodies.component(0).pinned_dofs().empty());
    FullOrderModel    model(bodies, ObservedDofs(2));
    const std::string m = message_of([&]() {
      model.set_state(SceneState(scene));
      model.solve();
    });
    EXPECT_NE(m.find("the position of a body held by contact alone is not "
                     "determined"),
              std::string::npos)
      << m;
    EXPECT_NE(m.find("P2: translation along (0, 1)"), std::string::npos) << m;
    // No other start changes that: the message is final, not retried.
    EXPECT_EQ(m.find("Solved again"), std::string::npos) << m;
  }
  std::string alone = roller;
  alone.replace(alone.find("set contact pairs = interface"),
                std::string("set contact pairs = interface").size(),
                "set contact pairs =");
  alone.erase(alone.find("subsection Contact interface"));
  std::string m = message_of_building(alone);
  EXPECT_NE(m.find("Component P2: its clamps and supports leave a "
                   "rigid-body motion free (translation along (0, 1)), and "
                   "no contact pair can hold it"),
            std::string::npos)
    << m;
  std::string none = stacked_scene(false);
  none.replace(none.find("  set clamped faces = right\n"),
               std::string("  set clamped faces = right\n").size(),
               "");
  none.replace(none.find("set contact pairs = interface"),
               std::string("set contact pairs = interface").size(),
               "set contact pairs =");
  none.erase(none.find("subsection Contact interface"));
  m = message_of_building(none);
  EXPECT_NE(m.find("Component P2: its clamps and supports leave a "
                   "rigid-body motion free ("),
            std::string::npos)
    << m;
  EXPECT_NE(m.find("(and 2 more)"), std::string::npos) << m;
}


namespace
{
  // The stacked rectangles with a load history @p stages (inserted into
  // the Scene subsection) and the Stage subsections @p sections.
  std::string
  staged_scene(const std::string &stages, const std::string &sections)
  {
    std::string       text  = stacked_scene(false);
    const std::string pairs = "  set contact pairs = interface\n";
    text.replace(text.find(pairs), pairs.size(), pairs + stages);
    return text + sections;
  }
} // namespace


// A one-stage history of every load is today's proportional loading, bit
// for bit: through the full-order model (FullOrderContact's own stepping)
// and through a ContactSolver on the dense problem.
TEST(LoadStages, OneStageIsTheProportionalLoadBitForBit)
{
  const Scene plain  = Scene::read_from_string(stacked_scene(false));
  const Scene staged = Scene::read_from_string(
    staged_scene("  set load stages = all\n",
                 "subsection Stage all\n  set loads = P1.tip\n"
                 "  set load steps = 3\nend\n"));
  ASSERT_EQ(staged.load_stages.size(), 1u);
  EXPECT_EQ(staged.load_stages[0].n_load_steps, 3u);
  ContactScene   plain_bodies(plain, 0), staged_bodies(staged, 0);
  FullOrderModel proportional(plain_bodies, ObservedDofs(2));
  proportional.set_n_load_steps(3);
  FullOrderModel        history(staged_bodies, ObservedDofs(2));
  const ContactSolution a = proportional.solve(), b = history.solve();
  ASSERT_GT(a.count(ContactStatus::stick) + a.count(ContactStatus::slip), 0u);
  ASSERT_GT(a.normal_force, 0.);
  EXPECT_EQ(b.n_load_steps, 3u);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.status, b.status);
  for (unsigned int i = 0; i < a.p.size(); ++i)
    {
      EXPECT_EQ(a.p[i], b.p[i]) << i;
      EXPECT_EQ(a.g[i], b.g[i]) << i;
    }

  ContactProblem problem;
  problem.W         = proportional.solver().flexibility();
  problem.g_load    = proportional.solver().load_gaps();
  problem.g_initial = plain_bodies.interface().initial_gaps();
  problem.mu        = plain_bodies.interface().friction_coefficients();
  const ActiveSetSolver solver;
  const ContactState    c = solver.solve(problem, 1., 3, "test");
  problem.stages          = {GapLoadStage{problem.g_load, 3, {}}};
  const ContactState d    = solver.solve(problem, 1., 7, "test");
  EXPECT_EQ(c.iterations, d.iterations); // 3 steps, not 7
  EXPECT_EQ(c.status, d.status);
  for (unsigned int i = 0; i < c.p.size(); ++i)
    EXPECT_EQ(c.p[i], d.p[i]) << i;
}


// solve_in_load_steps() on a made-up history of two stages (one node; the
// "solver" returns the free gaps plus a tangential shift): stage 2 ramps
// its own load on top of stage 1's held at full value, and every step
// starts from the state the previous step returned, across the stages too.
TEST(LoadStages, StagesHoldEarlierLoadsAndCarryTheState)
{
  Vector<double> g_initial(2), first(2), second(2);
  g_initial[0] = 1;
  first[0]     = -2;
  second[1]    = 3;
  std::vector<LoadStep>     seen;
  std::vector<ContactState> returned;
  const ContactState        last = solve_in_load_steps(
    g_initial,
    {GapLoadStage{first, 2, {}}, GapLoadStage{second, 3, {}}},
    0.5,
    [&](const LoadStep &step) {
      seen.push_back(step);
      ContactState state;
      state.g = step.g_free;
      state.g[1] += 0.25 * step.step;
      state.p.reinit(2);
      state.p[0]       = step.step;
      state.status     = {step.stage == 0 ? ContactStatus::stick
                                                 : ContactStatus::slip};
      state.slip_sign  = {int(step.step)};
      state.iterations = 1;
      returned.push_back(state);
      return state;
    });
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_EQ(last.iterations, 5u);
  const double expected_normal[]     = {0.5, 0, 0, 0, 0};
  const double expected_tangential[] = {0, 0, 0.5, 1, 1.5};
  for (unsigned int i = 0; i < 5; ++i)
    {
      EXPECT_EQ(seen[i].step, i + 1);
      EXPECT_EQ(seen[i].stage, i < 2 ? 0u : 1u);
      EXPECT_DOUBLE_EQ(seen[i].g_free[0], expected_normal[i]) << i;
      EXPECT_DOUBLE_EQ(seen[i].g_free[1], expected_tangential[i]) << i;
      const Vector<double> &g_before = i == 0 ? g_initial : returned[i - 1].g;
      EXPECT_EQ(seen[i].g_previous[0], g_before[0]) << i;
      EXPECT_EQ(seen[i].g_previous[1], g_before[1]) << i;
      EXPECT_EQ(seen[i].previous.p[0], i == 0 ? 0. : returned[i - 1].p[0]);
      EXPECT_EQ(seen[i].previous.status[0],
                i == 0 ? ContactStatus::open : returned[i - 1].status[0]);
    }
}


// A bad load history is refused when the scene is read, naming the file
// and the key: an unknown load, a load in two stages or in none, a stage
// without loads, zero steps.
TEST(LoadStages, BadStageListsAreRefusedWithTheFileAndTheKey)
{
  const auto message = [](const std::string &stages,
                          const std::string &sections) {
    return read_error(staged_scene(stages, sections));
  };
  const std::string two = "  set load stages = first, second\n";
  std::string       m   = message(two,
                          "subsection Stage first\n  set loads = P1.tip\n"
                                  "end\nsubsection Stage second\n"
                                  "  set loads = P1.tap\nend\n");
  EXPECT_NE(m.find("Scene file <test.prm>: Stage second: loads: <P1.tap> is "
                   "not a load of the scene"),
            std::string::npos)
    << m;
  EXPECT_NE(m.find("it has: P1.tip."), std::string::npos) << m;
  m = message(two,
              "subsection Stage first\n  set loads = P1.tip\n"
              "end\nsubsection Stage second\n  set loads = P1.tip\nend\n");
  EXPECT_NE(m.find("test.prm>: Stage second: loads: <P1.tip> is already in "
                   "stage first"),
            std::string::npos)
    << m;
  m = message(two,
              "subsection Stage first\n  set loads = P1.tip\n"
              "end\nsubsection Stage second\n  set loads =\nend\n");
  EXPECT_NE(m.find("test.prm>: Stage second: loads: a stage needs at least "
                   "one load"),
            std::string::npos)
    << m;
  m = message("  set load stages = first\n",
              "subsection Stage first\n  set loads = P1.tip\n"
              "  set load steps = 0\nend\n");
  EXPECT_NE(m.find("test.prm>: Stage first: load steps must be at least 1, "
                   "got 0."),
            std::string::npos)
    << m;
  m = message("  set load stages = first\n",
              "subsection Stage first\n  set loads = P1.tip\n"
              "  set load steps = 2000000000\nend\n");
  EXPECT_NE(m.find("test.prm>: Stage first: load steps must be at most 1000 "
                   "(each step is a contact solve), got 2000000000."),
            std::string::npos)
    << m;
  // A load in no stage: the stacked scene with a second load on P2.
  std::string       text  = staged_scene("  set load stages = first\n",
                                  "subsection Stage first\n"
                                         "  set loads = P1.tip\nend\n");
  const std::string clamp = "  set clamped faces = right\n";
  text.replace(text.rfind(clamp),
               clamp.size(),
               clamp + "  set loads = push\n  subsection Load push\n"
                       "    set face = left\n    set total force = 1\n"
                       "  end\n");
  m = read_error(text);
  EXPECT_NE(m.find("test.prm>: Scene: load stages: the load <P2.push> is in "
                   "no stage"),
            std::string::npos)
    << m;
  // A stage the list does not name is an unknown subsection.
  m = message("", "subsection Stage first\n  set loads = P1.tip\nend\n");
  EXPECT_NE(m.find("Stage first"), std::string::npos) << m;
}


// Cattaneo-Mindlin partial slip on the Hertz geometry (prm/
// cattaneo-mindlin.prm: one material, mu = 0.3), pressed down in a first
// load stage and moved sideways in a second: for two sideways
// displacements (Q / (mu P) = 0.46 and 0.80) the stick zone's half-width
// c lies within two slave-node spacings of a sqrt(1 - Q / (mu P)), with a
// the contact half-width of the same solution, and it sits in the middle
// of the contact.
TEST(Validation, CattaneoMindlinStickZone)
{
  const Scene scene = Scene::read(source_dir + "/prm/cattaneo-mindlin.prm");
  ASSERT_EQ(scene.load_stages.size(), 2u);
  const auto  &arc   = scene.components[0].mesh.arcs.begin()->second;
  const double mu    = scene.contact_pairs[0].friction_coefficient;
  unsigned int shear = 0;
  for (unsigned int l = 0; l < scene.components[0].loads.size(); ++l)
    if (scene.components[0].loads[l].name == "shear")
      shear = l;
  ContactScene   bodies(scene, 0);
  FullOrderModel full(bodies, ObservedDofs(2));
  for (const double shift : {20e-6, 36e-6})
    {
      SceneState state(scene);
      state.load_forces[0][shear] = shift;
      full.set_state(state);
      const ContactSolution s = full.solve();
      const auto            profile =
        HertzTheory::profile(bodies.interface(),
                             s,
                             0,
                             Point<2>(arc.centre[0],
                                      arc.centre[1] - arc.radius),
                             1.);
      const auto   zone  = HertzTheory::contact_zone(profile);
      const auto   stick = HertzTheory::stick_zone(profile);
      const double ratio = std::abs(s.tangential_force) / (mu * s.normal_force);
      EXPECT_GT(ratio, 0.2) << shift;
      EXPECT_LT(ratio, 0.95) << shift;
      EXPECT_GT(s.count(ContactStatus::slip), 0u) << shift;
      const double c = HertzTheory::stick_half_width(zone.half_width,
                                                     s.tangential_force,
                                                     mu,
                                                     s.normal_force);
      EXPECT_NEAR(stick.half_width, c, 2 * stick.node_spacing)
        << "u_x = " << shift << ", Q/(mu P) = " << ratio;
      EXPECT_NEAR(stick.centre, 0., 2 * stick.node_spacing) << shift;
    }
}

// The contact patch test (prm/patch-test.prm, doc/validation.md): two
// blocks of one material under a uniform compression, whose exact solution
// is a uniform pressure p = E delta / ((1 - nu^2) H) (plane strain) and a
// linear displacement field. On matching meshes node-to-segment contact
// passes it to round-off; on non-matching meshes (the slave face finer,
// then coarser) it does not, and the errors stay below the bounds measured
// by build/patch_test (with a margin). Force balance holds to round-off on
// every mesh: the supports' reactions equal the contact force and every
// free DoF is in equilibrium.
TEST(Validation, ContactPatchTest)
{
  const Scene scene     = Scene::read(source_dir + "/prm/patch-test.prm");
  const auto  errors_of = [&](const unsigned int slave_cells,
                             const unsigned int master_cells) {
    Scene s                         = scene;
    s.components[0].subdivisions[0] = slave_cells;
    s.components[1].subdivisions[0] = master_cells;
    ContactScene   bodies(s, 0);
    FullOrderModel full(bodies, ObservedDofs(2));
    full.set_state(SceneState(s));
    const ContactSolution solution = full.solve();
    const auto           &upper    = s.components[0];
    return PatchTest::measure(bodies.components(),
                              bodies.interface(),
                              solution,
                              {s.plane_model,
                               upper.zones[0].youngs_modulus,
                               upper.zones[0].poissons_ratio,
                               upper.upper_right[1] -
                                 s.components[1].lower_left[1],
                               -upper.supports[0].displacement[1]});
  };
  // p = 210e9 / (1 - 0.09) * 1e-5 / 0.1, computed by hand.
  const PatchTest::UniaxialCompression exact{PlaneModel::plane_strain,
                                             210e9,
                                             0.3,
                                             0.1,
                                             1e-5};
  EXPECT_NEAR(exact.pressure(), 2.3076923076923077e7, 1e-6);

  const PatchTest::Errors matching = errors_of(5, 5);
  EXPECT_EQ(matching.n_closed, matching.n_slave_nodes);
  EXPECT_LT(matching.max_pressure_error, 1e-9);
  EXPECT_LT(matching.max_displacement_error, 1e-9);
  EXPECT_NEAR(matching.contact_force,
              matching.exact_force,
              1e-9 * matching.exact_force);
  // Measured (build/patch_test, Q2 at the scene's mesh): slave finer 7:5,
  // pressure 5.48e-2, displacement 8.47e-3, force -2.92e-4; slave coarser
  // 5:7, 0.224, 2.64e-2, -4.96e-3. The bounds leave 10 to 40 %: a change
  // of the contact discretisation that makes it worse fails.
  const std::tuple<unsigned int, unsigned int, double, double, double>
    non_matching[] = {{7, 5, 0.06, 0.01, 4e-4}, {5, 7, 0.25, 0.03, 6e-3}};
  for (const auto &[slave, master, pressure, displacement, force] :
       non_matching)
    {
      const PatchTest::Errors e = errors_of(slave, master);
      SCOPED_TRACE(std::to_string(slave) + ":" + std::to_string(master));
      EXPECT_EQ(e.n_closed, e.n_slave_nodes);
      EXPECT_GT(e.max_pressure_error, 1e-3); // it does not pass exactly
      EXPECT_LT(e.max_pressure_error, pressure);
      EXPECT_LT(e.max_displacement_error, displacement);
      EXPECT_NEAR(e.contact_force, e.exact_force, force * e.exact_force);
    }
  for (const PatchTest::Errors &e :
       {matching, errors_of(7, 5), errors_of(5, 7)})
    {
      EXPECT_LT(e.reaction_balance, 1e-10);
      EXPECT_LT(e.equilibrium_residual, 1e-10);
      ASSERT_EQ(e.reactions.size(), 2u);
      EXPECT_LT(e.reactions[0], 0.); // the press pushes the upper block down
      EXPECT_GT(e.reactions[1], 0.); // the base holds the lower block up
    }
}
