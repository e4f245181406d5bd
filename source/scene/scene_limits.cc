#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/scene/scene_limits.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace FuzzyContact
{
  namespace SceneLimits
  {
    double
    youngs_modulus(const double value, const std::string &what)
    {
      return Input::in_range(value,
                             min_youngs_modulus,
                             max_youngs_modulus,
                             what,
                             "a Young's modulus in Pa, from foam to diamond");
    }


    double
    density(const double value, const std::string &what)
    {
      return Input::in_range(value,
                             min_density,
                             max_density,
                             what,
                             "a density in kg/m^3");
    }


    double
    force(const double value, const std::string &what)
    {
      return Input::in_range(value,
                             -max_force,
                             max_force,
                             what,
                             "a force in N");
    }


    std::optional<double>
    optional_force(const std::string &text,
                   const std::string &keyword,
                   const std::string &what)
    {
      const std::string value = Utilities::trim(text);
      if (value == keyword)
        return std::nullopt;
      return force(
        Input::to_double(value, what + " (a force in N, or " + keyword + ")"),
        what);
    }


    double
    friction_coefficient(const double value, const std::string &what)
    {
      return Input::in_range(value,
                             0,
                             max_friction,
                             what,
                             "a Coulomb friction coefficient");
    }


    Tensor<1, 2>
    gravity(const Tensor<1, 2> &g, const std::string &what)
    {
      for (unsigned int d = 0; d < 2; ++d)
        Input::finite(g[d], what);
      Input::in_range(g.norm(),
                      0,
                      max_gravity,
                      what + " (its magnitude)",
                      "an acceleration in m/s^2, up to about 1000 times the "
                      "Earth's");
      return g;
    }


    namespace
    {
      void
      check_component(const ComponentDescription &component)
      {
        const std::string where = "Component " + component.name;
        for (unsigned int d = 0; d < 2; ++d)
          for (const double x :
               {component.lower_left[d], component.upper_right[d]})
            Input::in_range(x,
                            -max_coordinate,
                            max_coordinate,
                            where + ": the corners' coordinates",
                            "in m");
        Input::in_range(component.length(),
                        min_length,
                        max_length,
                        where + ": length (upper right x - lower left x)",
                        "in m");
        Input::in_range(component.height(),
                        min_length,
                        max_length,
                        where + ": height (upper right y - lower left y)",
                        "in m");
        Input::in_range(component.thickness,
                        min_length,
                        max_length,
                        where + ": thickness",
                        "in m");
        for (const unsigned int n : component.subdivisions)
          Input::integer_in_range(n,
                                  1,
                                  max_subdivisions,
                                  where + ": subdivisions (each)");
        const double cells =
          component.is_rectangle()
            ? 1.0 * component.subdivisions[0] * component.subdivisions[1]
            : 1.0 * component.mesh.n_cells;
        Input::in_range(cells,
                        1,
                        max_cells,
                        where + ": subdivisions (their product, the cells)",
                        "a mesh this machine can hold");
        for (const MaterialZone &zone : component.zones)
          {
            const std::string zwhere =
              component.implicit_zone ? where : where + ", zone " + zone.name;
            youngs_modulus(zone.youngs_modulus, zwhere + ": E");
            density(zone.density, zwhere + ": rho");
            Input::in_range(zone.poissons_ratio,
                            min_poissons_ratio,
                            max_poissons_ratio,
                            zwhere + ": nu",
                            "nearly incompressible materials need other "
                            "elements");
          }
        for (const EdgeLoad &load : component.loads)
          if (!load.is_weight) // (the scene's gravity, checked on its own)
            force(load.total_force,
                  where + ", load " + load.name +
                    (load.is_pressure ? ": pressure" : ": total force"));
        for (const Support &support : component.supports)
          for (unsigned int d = 0; d < 2; ++d)
            Input::in_range(support.displacement[d],
                            -max_length,
                            max_length,
                            where + ", support " + support.name +
                              ": displacement",
                            "in m");
      }
    } // namespace


    void
    check_ranges(const Scene &scene)
    {
      gravity(scene.gravity, "Scene: gravity");
      double largest = 0;
      for (const ComponentDescription &component : scene.components)
        {
          check_component(component);
          largest = std::max({largest, component.length(), component.height()});
        }
      for (const ContactPairDescription &pair : scene.contact_pairs)
        {
          const std::string where = "Contact " + pair.name;
          friction_coefficient(pair.friction_coefficient,
                               where + ": friction coefficient");
          if (pair.has_initial_gap)
            Input::in_range(pair.initial_gap,
                            -largest,
                            largest,
                            where + ": initial gap",
                            "in m, at most the size of the largest component");
        }
    }


    namespace
    {
      // Nodes along the x and y edges of component c after r refinements.
      std::array<double, 2>
      nodes_per_edge(const ComponentDescription &c, const unsigned int r)
      {
        std::array<double, 2> n;
        for (unsigned int d = 0; d < 2; ++d)
          n[d] = c.subdivisions[d] * std::ldexp(1.0, r) * c.fe_degree + 1;
        return n;
      }

      double
      face_nodes(const ComponentDescription &c,
                 const std::string          &face,
                 const unsigned int          r)
      {
        return c.n_mesh_faces(face) * std::ldexp(1.0, r) * c.fe_degree + 1;
      }
    } // namespace


    double
    n_dofs(const Scene &scene, const unsigned int c, const unsigned int r)
    {
      const ComponentDescription &component = scene.components[c];
      if (!component.is_rectangle())
        {
          // Nodes of Q_p on quadrilaterals: p^2 per cell, plus those on the
          // boundary edges (an upper bound for any mesh).
          double boundary = 0;
          for (const auto &[id, n] : component.mesh.boundary_faces)
            boundary += n;
          const double p = component.fe_degree, s = std::ldexp(1.0, r);
          return 2 * (component.mesh.n_cells * s * s * p * p +
                      boundary * s * p + 1);
        }
      const auto n = nodes_per_edge(scene.components[c], r);
      return 2 * n[0] * n[1];
    }


    double
    estimated_memory(const Scene       &scene,
                     const unsigned int refinements,
                     const bool         static_correction)
    {
      // Per DoF: two sparse matrices of a vector Q_p element, their
      // pattern, a sparse Cholesky factor with its fill-in and work
      // vectors; measured below 3 kB on the default scenes, taken as 4 kB.
      constexpr double bytes_per_dof = 4096;
      double           bytes         = 200e6; // the program and its libraries
      for (unsigned int c = 0; c < scene.components.size(); ++c)
        {
          const ComponentDescription &component = scene.components[c];
          const double                n         = n_dofs(scene, c, refinements);
          bytes += bytes_per_dof * n;
          if (!static_correction)
            continue;
          // Static correction: one DoF-long vector per DoF of a contact
          // face (at most the whole face) and per load. Measured peak
          // memory of step-3 on the tests/fuzz scene: 0.40 GB at 3
          // refinements (estimated 0.49 GB), 1.40 GB at 4 (estimated
          // 1.98 GB).
          std::set<std::string> faces;
          for (const ContactPairDescription &pair : scene.contact_pairs)
            {
              if (pair.slave_component == component.name)
                faces.insert(pair.slave_face);
              if (pair.master_component == component.name)
                faces.insert(pair.master_face);
            }
          double columns = component.loads.size();
          for (const std::string &f : faces)
            columns += 2 * face_nodes(component, f, refinements);
          bytes += 8 * n * columns;
        }
      return bytes;
    }


    void
    check_memory(const Scene       &scene,
                 const unsigned int refinements,
                 const bool         static_correction,
                 const std::string &key)
    {
      const double bytes =
        estimated_memory(scene, refinements, static_correction);
      if (bytes <= memory_budget)
        return;
      double dofs = 0;
      for (unsigned int c = 0; c < scene.components.size(); ++c)
        dofs += n_dofs(scene, c, refinements);
      std::ostringstream message;
      message << std::setprecision(3) << key << " = " << refinements
              << " gives about " << dofs << " DoFs in scene <" << scene.name
              << "> and an estimated " << bytes / std::pow(1024.0, 3)
              << " GiB of memory"
              << (static_correction ? " (with the static correction modes)"
                                    : "")
              << "; this machine allows " << memory_budget / std::pow(1024.0, 3)
              << " GiB. Lower " << key
              << " or the subdivisions of the scene's components.";
      AssertThrow(false, ExcMessage(message.str()));
    }


    std::vector<std::string>
    warnings(const Scene &scene)
    {
      std::vector<std::string> found;
      bool                     any_load = false;
      for (const ComponentDescription &component : scene.components)
        for (const EdgeLoad &load : component.loads)
          {
            any_load = any_load || load.total_force != 0;
            if (std::find(component.clamped_faces.begin(),
                          component.clamped_faces.end(),
                          load.face) != component.clamped_faces.end())
              found.push_back("Component " + component.name + ", load " +
                              load.name + ": it acts on the clamped face <" +
                              load.face +
                              ">, so it moves nothing and every response "
                              "to it is zero.");
          }
      if (!any_load)
        found.push_back("Scene <" + scene.name +
                        ">: no load with a non-zero force; every response "
                        "is zero.");
      return found;
    }
  } // namespace SceneLimits
} // namespace FuzzyContact
