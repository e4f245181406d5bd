// The plain parts of a scene description (scene/scene.h): names of plane
// models and faces, and what a component description answers about its
// faces, supports and zones.

#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  std::string
  to_string(const PlaneModel model)
  {
    return model == PlaneModel::plane_stress ? "plane stress" : "plane strain";
  }


  std::string
  to_string(const Face face)
  {
    switch (face)
      {
        case Face::left:
          return "left";
        case Face::right:
          return "right";
        case Face::bottom:
          return "bottom";
        case Face::top:
          return "top";
      }
    return "unknown";
  }


  Face
  face_from_string(const std::string &name, const std::string &what)
  {
    const std::string n = Utilities::trim(name);
    if (n == "left")
      return Face::left;
    if (n == "right")
      return Face::right;
    if (n == "bottom")
      return Face::bottom;
    if (n == "top")
      return Face::top;
    AssertThrow(false,
                ExcMessage(what + ": <" + n +
                           "> is not a face of a rectangular component; "
                           "use left, right, bottom or top."));
    return Face::left;
  }


  std::optional<Face>
  rectangle_side(const std::string &name)
  {
    const std::string n = Utilities::trim(name);
    for (const Face f : {Face::left, Face::right, Face::bottom, Face::top})
      if (n == to_string(f))
        return f;
    return std::nullopt;
  }


  bool
  ComponentDescription::is_rectangle() const
  {
    return mesh_file.empty();
  }


  types::boundary_id
  ComponentDescription::boundary_id(const std::string &face,
                                    const std::string &what) const
  {
    if (is_rectangle())
      return static_cast<types::boundary_id>(face_from_string(face, what));
    const auto id = mesh.boundary_ids.find(Utilities::trim(face));
    AssertThrow(id != mesh.boundary_ids.end(),
                ExcMessage(what + ": <" + mesh.file + "> has no " +
                           mesh.face_kind() + " called <" +
                           Utilities::trim(face) +
                           ">; it has: " + mesh.face_names() + "."));
    return id->second;
  }


  std::vector<Support>
  ComponentDescription::all_supports() const
  {
    std::vector<Support> all;
    for (const std::string &face : clamped_faces)
      all.push_back(Support{"clamp " + face, face, {{true, true}}, {}});
    all.insert(all.end(), supports.begin(), supports.end());
    return all;
  }


  unsigned int
  ComponentDescription::n_mesh_faces(const std::string &face) const
  {
    if (is_rectangle())
      {
        const Face f = face_from_string(face, "Component " + name);
        return (f == Face::left || f == Face::right) ? subdivisions[1]
                                                     : subdivisions[0];
      }
    const auto n = mesh.boundary_faces.find(boundary_id(face, name));
    return n == mesh.boundary_faces.end() ? 0 : n->second;
  }


  double
  ComponentDescription::face_length(const std::string &face) const
  {
    if (is_rectangle())
      {
        const Face f = face_from_string(face, "Component " + name);
        return (f == Face::left || f == Face::right) ? height() : length();
      }
    const auto l = mesh.boundary_lengths.find(boundary_id(face, name));
    return l == mesh.boundary_lengths.end() ? 0. : l->second;
  }


  double
  ComponentDescription::length() const
  {
    return upper_right[0] - lower_left[0];
  }


  double
  ComponentDescription::height() const
  {
    return upper_right[1] - lower_left[1];
  }


  unsigned int
  ComponentDescription::zone_index(const std::string &zone_name) const
  {
    for (unsigned int z = 0; z < zones.size(); ++z)
      if (zones[z].name == zone_name)
        return z;
    AssertThrow(false,
                ExcMessage("Component " + name + " has no zone called <" +
                           zone_name + ">."));
    return 0;
  }


  double
  ComponentDescription::zone_area(const unsigned int z) const
  {
    AssertIndexRange(z, zones.size());
    const MaterialZone &zone = zones[z];
    if (!is_rectangle())
      {
        if (implicit_zone)
          {
            double area = 0;
            for (const auto &[id, a] : mesh.material_areas)
              area += a;
            return area;
          }
        const auto a = mesh.material_areas.find(zone.material_id);
        return a == mesh.material_areas.end() ? 0. : a->second;
      }
    const double dx = std::min(zone.x_range[1], upper_right[0]) -
                      std::max(zone.x_range[0], lower_left[0]);
    const double dy = std::min(zone.y_range[1], upper_right[1]) -
                      std::max(zone.y_range[0], lower_left[1]);
    return std::max(dx, 0.) * std::max(dy, 0.);
  }
} // namespace FuzzyContact
