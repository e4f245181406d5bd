// Abaqus input files (.inp) as component meshes, read through deal.II's
// GridIn::read_abaqus.
//
// deal.II's reader takes boundary ids from the digits of a surface's name
// (`*Surface, name=SS3` is boundary 3) and material ids from the digits
// after a '-' in the material of a `*Solid Section`; it cannot use names.
// abaqus_grid_in_text() therefore reads the names from the file, gives each
// surface and each element set an id, and hands deal.II a rewritten text
// with these ids in place of the names. It reads no element itself beyond
// checking each element's number of nodes and restoring the digits of the
// node coordinates that deal.II's reader rounds off, (first-order
// quadrilaterals only: triangles and second-order elements are refused with a
// hint) and the numbering (deal.II needs elements numbered 1, 2, ... in file
// order).

#ifndef fuzzycontact_scene_abaqus_file_h
#define fuzzycontact_scene_abaqus_file_h

#include <fuzzycontact/scene/mesh_file.h>

#include <string>

namespace FuzzyContact
{
  /**
   * Reads the names of the Abaqus input text @p text (the content of
   * info.file) into @p info: its element-based surfaces are the faces
   * (boundary ids 1, 2, ... in file order), its element sets not marked
   * `internal` are the zones (material ids 1, 2, ...; a cell in no such set
   * has material id 0). Returns the text for GridIn::read_abaqus: nodes,
   * elements and element sets as in the file, each surface named by its
   * id, one `*Solid Section` per zone (the file's own sections dropped),
   * nothing from `*Step` on. Throws naming @p where and the file for
   * triangles, second-order elements, elements not numbered 1, 2, ...,
   * node-based surfaces, two zones sharing an element, names that differ
   * only in case, and a file without elements or without surfaces.
   */
  std::string
  abaqus_grid_in_text(const std::string &text,
                      MeshFileInfo      &info,
                      const std::string &where);

  /**
   * deal.II 9.4's Abaqus reader keeps 9 significant digits of each
   * coordinate (it goes through a UCD text written in scientific notation
   * with precision 8). This puts every vertex of @p triangulation, read
   * from @p grid_in_text, back at the coordinates of its node in the text
   * (those that round to one node only; the others keep their 9 digits).
   */
  void
  restore_node_coordinates(const std::string &grid_in_text,
                           Triangulation<2>  &triangulation);
} // namespace FuzzyContact

#endif
