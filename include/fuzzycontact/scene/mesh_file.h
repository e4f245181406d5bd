// A component meshed outside FuzzyContact: a Gmsh mesh (.msh, ASCII format
// 2 or 4), a Gmsh geometry (.geo, meshed here by the gmsh program that
// comes with deal.II) or an Abaqus input file (.inp, abaqus_file.h).
//
// The names of the file's physical groups are what a scene file uses:
// physical curves are faces (clamps, supports, loads, contact faces),
// physical surfaces are material zones; in an Abaqus file, surfaces are
// faces and element sets zones. read_mesh_file() reads the file once
// when the scene is read, so that an unknown name, a triangle, an inverted
// cell or a file that cannot be read is refused before any computing;
// create_mesh() builds the deal.II triangulation from what it kept.
//
// Curved boundaries stay curved: every named boundary whose nodes lie on one
// circle (to 1e-6 of its radius; Gmsh writes its nodes exactly on the arcs
// of the geometry) gets deal.II's exact SphericalManifold, and the cells
// along it a TransfiniteInterpolationManifold, so that refinement and the
// mapping of the element's degree put new nodes on the arc itself.

#ifndef fuzzycontact_scene_mesh_file_h
#define fuzzycontact_scene_mesh_file_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * What a scene needs to know about a mesh file before any computing.
   */
  struct MeshFileInfo
  {
    /** The file as the scene names it, resolved to a path. */
    std::string file;
    /**
     * The text deal.II's GridIn reads: Gmsh ASCII (a .geo file: as meshed
     * by gmsh), or for an Abaqus file the text abaqus_grid_in_text() made.
     */
    std::string msh_text;
    bool        abaqus = false;
    /** Physical curves (faces) and surfaces (zones) by name. */
    std::map<std::string, types::boundary_id> boundary_ids;
    std::map<std::string, types::material_id> material_ids;
    /** Area [m^2] of each physical surface, after scaling. */
    std::map<types::material_id, double> material_areas;
    /** Number of mesh faces (edges) of each physical curve. */
    std::map<types::boundary_id, unsigned int> boundary_faces;
    /** Length of each physical curve [m] (its straight mesh edges). */
    std::map<types::boundary_id, double> boundary_lengths;
    /** Bounding box of the mesh [m], after scaling. */
    Point<2> lower_left, upper_right;
    /** Number of cells and of vertices of the mesh as read. */
    unsigned int n_cells    = 0;
    unsigned int n_vertices = 0;
    /** Named boundaries that are circular arcs: centre and radius [m]. */
    struct Arc
    {
      Point<2> centre;
      double   radius;
    };
    std::map<types::boundary_id, Arc> arcs;

    /** "name1, name2, ..." of the faces, or of the zones. */
    std::string
    face_names() const;
    std::string
    zone_names() const;
    /** What the file calls a face ("physical curve" or "surface") and a
     * zone ("physical surface" or "element set"). */
    std::string
    face_kind() const;
    std::string
    zone_kind() const;
  };

  /**
   * Reads and checks the mesh file @p file (.msh, .geo or .inp), with the
   * mesh's coordinates multiplied by @p scale. @p where names the key that gave
   * the file ("Component Roller: mesh file"). Throws a message naming the
   * file for a file that cannot be read or meshed, a binary .msh, a mesh
   * with triangles (saying how to recombine it), an inverted or degenerate
   * cell, and a mesh without physical curves (Abaqus: without surfaces;
   * see abaqus_grid_in_text() for its own checks).
   */
  MeshFileInfo
  read_mesh_file(const std::string &file,
                 const double       scale,
                 const std::string &where);

  /**
   * Builds the triangulation of @p info (coordinates times @p scale), with
   * the ids of info.boundary_ids and info.material_ids, and exact
   * manifolds on the circular arcs.
   */
  void
  create_mesh(const MeshFileInfo &info,
              const double        scale,
              Triangulation<2>   &triangulation,
              const std::string  &where);
} // namespace FuzzyContact

#endif
