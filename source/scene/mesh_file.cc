#include <fuzzycontact/base/input.h>
#include <fuzzycontact/scene/abaqus_file.h>
#include <fuzzycontact/scene/mesh_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

namespace FuzzyContact
{
  namespace
  {
    // Manifold ids: an arc's boundary id + arc_manifold_offset on its faces,
    // transfinite_manifold_id on the cells along any arc.
    constexpr types::manifold_id arc_manifold_offset     = 1000;
    constexpr types::manifold_id transfinite_manifold_id = 999;

    std::string
    extension_of(const std::string &file)
    {
      std::string e = std::filesystem::path(file).extension().string();
      std::transform(e.begin(), e.end(), e.begin(), [](const unsigned char c) {
        return static_cast<char>(std::tolower(c));
      });
      return e;
    }

    // Meshes a .geo file with the gmsh program into a temporary .msh file
    // and returns its text; the temporary file is removed.
    std::string
    mesh_geo_file(const std::string &file, const std::string &where)
    {
      static unsigned int         counter = 0;
      const std::filesystem::path output =
        std::filesystem::temp_directory_path() /
        ("fuzzycontact-" + std::to_string(::getpid()) + "-" +
         std::to_string(counter++) + ".msh");
      const std::string command = "gmsh -2 -format msh41 -v 2 -o '" +
                                  output.string() + "' '" + file + "' 2>&1";
      std::string log;
      int         status = -1;
      if (FILE *pipe = ::popen(command.c_str(), "r"))
        {
          char buffer[512];
          while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr)
            log += buffer;
          status = ::pclose(pipe);
        }
      std::string text;
      if (std::filesystem::exists(output))
        {
          std::ifstream      in(output);
          std::ostringstream s;
          s << in.rdbuf();
          text = s.str();
          std::filesystem::remove(output);
        }
      AssertThrow(status == 0 && !text.empty() &&
                    log.find("Error") == std::string::npos,
                  ExcMessage(where + ": gmsh could not mesh <" + file +
                             "> (exit status " + std::to_string(status) +
                             "): " + Utilities::trim(log)));
      return text;
    }

    // The text between "$Section" and "$EndSection", empty if absent.
    std::string
    section(const std::string &text, const std::string &name)
    {
      const std::string begin = "$" + name, end = "$End" + name;
      const auto        b = text.find(begin);
      if (b == std::string::npos)
        return "";
      const auto e = text.find(end, b);
      return text.substr(b + begin.size(),
                         e == std::string::npos ? std::string::npos
                                                : e - b - begin.size());
    }

    // Physical names: dimension 1 are faces, dimension 2 zones.
    void
    read_physical_names(MeshFileInfo &info, const std::string &where)
    {
      std::istringstream in(section(info.msh_text, "PhysicalNames"));
      unsigned int       n = 0;
      in >> n;
      for (unsigned int i = 0; i < n; ++i)
        {
          int         dim = -1, tag = -1;
          std::string rest;
          in >> dim >> tag;
          std::getline(in, rest);
          const auto q0 = rest.find('"'), q1 = rest.rfind('"');
          AssertThrow(in && q0 != std::string::npos && q1 > q0 && tag >= 0,
                      ExcMessage(where + ": <" + info.file +
                                 ">: unreadable $PhysicalNames entry " +
                                 std::to_string(i + 1) + "."));
          const std::string name = rest.substr(q0 + 1, q1 - q0 - 1);
          if (dim == 1)
            info.boundary_ids[name] = static_cast<types::boundary_id>(tag);
          else if (dim == 2)
            info.material_ids[name] = static_cast<types::material_id>(tag);
        }
    }

    // The 2D Jacobian determinant at each vertex of a quadrilateral (deal.II
    // numbers its vertices lexicographically); all positive for a valid cell.
    bool
    cell_is_valid(const Triangulation<2>::active_cell_iterator &cell)
    {
      const auto cross = [](const Tensor<1, 2> &a, const Tensor<1, 2> &b) {
        return a[0] * b[1] - a[1] * b[0];
      };
      const Point<2> v0 = cell->vertex(0), v1 = cell->vertex(1),
                     v2 = cell->vertex(2), v3 = cell->vertex(3);
      return cross(v1 - v0, v2 - v0) > 0 && cross(v1 - v0, v3 - v1) > 0 &&
             cross(v3 - v2, v2 - v0) > 0 && cross(v3 - v2, v3 - v1) > 0;
    }

    // Reads the Gmsh text into @p triangulation (no manifolds yet) and
    // checks the cells.
    void
    read_triangulation(const MeshFileInfo &info,
                       const double        scale,
                       Triangulation<2>   &triangulation,
                       const std::string  &where)
    {
      const std::string file = where + ": <" + info.file + ">";
      try
        {
          GridIn<2> grid_in;
          grid_in.attach_triangulation(triangulation);
          std::istringstream in(info.msh_text);
          if (info.abaqus)
            {
              grid_in.read_abaqus(in);
              restore_node_coordinates(info.msh_text, triangulation);
            }
          else
            grid_in.read_msh(in);
        }
      catch (const ExceptionBase &e)
        {
          AssertThrow(false,
                      ExcMessage(file + ": deal.II's GridIn cannot read it (" +
                                 Utilities::trim(Input::message_of(e)) +
                                 "). FuzzyContact reads first-order "
                                 "quadrilateral meshes in Gmsh's ASCII "
                                 "format 2 or 4 and Abaqus input files."));
        }
      AssertThrow(triangulation.all_reference_cells_are_hyper_cube(),
                  ExcMessage(file +
                             ": the mesh has triangles; FuzzyContact needs "
                             "quadrilaterals. Recombine them in Gmsh: add "
                             "'Recombine Surface{...};' (or 'Mesh.RecombineAll "
                             "= 1;') to the .geo file, or mesh with "
                             "'gmsh -2 -setnumber Mesh.RecombineAll 1 "
                             "-setnumber Mesh.Algorithm 8'."));
      GridTools::scale(scale, triangulation);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell_is_valid(cell))
          {
            std::ostringstream message;
            message << file << ": the cell centred at (" << cell->center()[0]
                    << ", " << cell->center()[1]
                    << ") is inverted or degenerate (its corners do not "
                       "turn one way); fix the mesh.";
            AssertThrow(false, ExcMessage(message.str()));
          }
    }

    // Least-squares circle through @p points (Kasa's fit); returns false
    // if the points lie on a straight line or off every circle.
    bool
    fit_circle(const std::vector<Point<2>> &points, MeshFileInfo::Arc &arc)
    {
      if (points.size() < 3)
        return false;
      // Straight: every point within round-off of the line through the
      // first point and the one farthest from it.
      Point<2> far = points[0];
      for (const Point<2> &p : points)
        if (p.distance(points[0]) > far.distance(points[0]))
          far = p;
      const double extent = far.distance(points[0]);
      if (extent == 0)
        return false;
      const Tensor<1, 2> d        = (far - points[0]) / extent;
      double             off_line = 0;
      for (const Point<2> &p : points)
        off_line = std::max(off_line,
                            std::abs((p - points[0])[0] * d[1] -
                                     (p - points[0])[1] * d[0]));
      if (off_line <= 1e-10 * extent)
        return false;
      // Kasa's fit on coordinates centred and scaled to the extent, so that
      // the 3 x 3 normal equations are well conditioned.
      Point<2> mean;
      for (const Point<2> &p : points)
        mean += p / static_cast<double>(points.size());
      FullMatrix<double> A(3, 3);
      Vector<double>     b(3), x(3);
      for (const Point<2> &p : points)
        {
          const Tensor<1, 2> q      = (p - mean) / extent;
          const double       row[3] = {q[0], q[1], 1.};
          const double       rhs    = -q.norm_square();
          for (unsigned int i = 0; i < 3; ++i)
            {
              b[i] += row[i] * rhs;
              for (unsigned int j = 0; j < 3; ++j)
                A(i, j) += row[i] * row[j];
            }
        }
      const double trace = A(0, 0) + A(1, 1) + A(2, 2);
      if (std::abs(A.determinant()) <= 1e-12 * std::pow(trace / 3, 3))
        return false;
      A.gauss_jordan();
      A.vmult(x, b);
      const Point<2> centre(-x[0] / 2, -x[1] / 2);
      const double   r2 = centre.square() - x[2];
      if (r2 <= 0)
        return false;
      arc.centre         = mean + extent * centre;
      arc.radius         = extent * std::sqrt(r2);
      double largest_off = 0;
      for (const Point<2> &p : points)
        largest_off =
          std::max(largest_off, std::abs(p.distance(arc.centre) - arc.radius));
      // A nearly straight line is a circle of enormous radius: not an arc.
      return largest_off <= 1e-6 * arc.radius && arc.radius < 1e6 * extent;
    }


    // Face counts, arcs, areas, bounding box of the triangulation.
    void
    measure(MeshFileInfo &info, const Triangulation<2> &triangulation)
    {
      std::map<types::boundary_id, std::set<unsigned int>> vertices;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          info.material_areas[cell->material_id()] += cell->measure();
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                ++info.boundary_faces[face->boundary_id()];
                info.boundary_lengths[face->boundary_id()] +=
                  face->vertex(0).distance(face->vertex(1));
                for (const unsigned int v : face->vertex_indices())
                  vertices[face->boundary_id()].insert(face->vertex_index(v));
              }
        }
      const auto &all = triangulation.get_vertices();
      for (const auto &[id, indices] : vertices)
        {
          std::vector<Point<2>> points;
          for (const unsigned int i : indices)
            points.push_back(all[i]);
          MeshFileInfo::Arc arc;
          if (id != 0 && fit_circle(points, arc))
            info.arcs[id] = arc;
        }
      const auto box   = GridTools::compute_bounding_box(triangulation);
      info.lower_left  = box.get_boundary_points().first;
      info.upper_right = box.get_boundary_points().second;
      info.n_cells     = triangulation.n_active_cells();
      info.n_vertices  = triangulation.n_used_vertices();
    }
  } // namespace


  std::string
  MeshFileInfo::face_names() const
  {
    std::string names;
    for (const auto &[name, id] : boundary_ids)
      names += (names.empty() ? "" : ", ") + name;
    return names.empty() ? "(none)" : names;
  }


  std::string
  MeshFileInfo::zone_names() const
  {
    std::string names;
    for (const auto &[name, id] : material_ids)
      names += (names.empty() ? "" : ", ") + name;
    return names.empty() ? "(none)" : names;
  }


  std::string
  MeshFileInfo::face_kind() const
  {
    return abaqus ? "surface" : "physical curve";
  }


  std::string
  MeshFileInfo::zone_kind() const
  {
    return abaqus ? "element set" : "physical surface";
  }


  MeshFileInfo
  read_mesh_file(const std::string &file,
                 const double       scale,
                 const std::string &where)
  {
    AssertThrow(std::filesystem::is_regular_file(file),
                ExcMessage(where + ": <" + file +
                           "> is not a file that exists (a relative path is "
                           "read from the scene file's folder)."));
    MeshFileInfo info;
    info.file             = file;
    const std::string ext = extension_of(file);
    AssertThrow(ext == ".msh" || ext == ".geo" || ext == ".inp",
                ExcMessage(where + ": <" + file +
                           ">: FuzzyContact reads Gmsh meshes (.msh), Gmsh "
                           "geometries (.geo) and Abaqus input files (.inp); "
                           "convert other formats with gmsh (e.g. 'gmsh -2 "
                           "-format msh41 file')."));
    Triangulation<2> triangulation;
    if (ext == ".inp")
      {
        info.abaqus = true;
        info.msh_text =
          abaqus_grid_in_text(Input::read_text_file(file), info, where);
        read_triangulation(info, scale, triangulation, where);
        measure(info, triangulation);
        return info;
      }
    if (ext == ".geo")
      {
        Input::read_text_file(file); // names the file if it is unreadable
        info.msh_text = mesh_geo_file(file, where);
      }
    else
      info.msh_text = Input::read_text_file(file);

    std::istringstream format(section(info.msh_text, "MeshFormat"));
    double             version = 0;
    int                binary  = -1;
    format >> version >> binary;
    AssertThrow(version >= 2 && version < 5 && binary == 0,
                ExcMessage(where + ": <" + file +
                           "> is not an ASCII Gmsh mesh of format 2 or 4 "
                           "(its $MeshFormat is missing, binary or of another "
                           "version); save it from Gmsh with "
                           "'Mesh.Binary = 0' and format 4.1 or 2.2."));
    read_physical_names(info, where);
    AssertThrow(!info.boundary_ids.empty(),
                ExcMessage(where + ": <" + file +
                           "> names no physical curve, so no face can be "
                           "clamped, loaded or put in contact; add "
                           "'Physical Curve(\"name\") = {...};' for each face "
                           "the scene uses."));
    read_triangulation(info, scale, triangulation, where);
    measure(info, triangulation);
    return info;
  }


  void
  create_mesh(const MeshFileInfo &info,
              const double        scale,
              Triangulation<2>   &triangulation,
              const std::string  &where)
  {
    read_triangulation(info, scale, triangulation, where);
    if (info.arcs.empty())
      return;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && info.arcs.count(face->boundary_id()) > 0)
          {
            cell->set_all_manifold_ids(transfinite_manifold_id);
            break;
          }
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && info.arcs.count(face->boundary_id()) > 0)
          face->set_manifold_id(arc_manifold_offset + face->boundary_id());
    for (const auto &[id, arc] : info.arcs)
      triangulation.set_manifold(arc_manifold_offset + id,
                                 SphericalManifold<2>(arc.centre));
    TransfiniteInterpolationManifold<2> transfinite;
    transfinite.initialize(triangulation);
    triangulation.set_manifold(transfinite_manifold_id, transfinite);
  }
} // namespace FuzzyContact
