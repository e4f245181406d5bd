// The contact pressure and shear along each contact pair's slave face, as
// every solver of a step-3 case found them (doc/contact.md, section 8):
// <stem>-face.dat, one block per pair and solver (index in the order pairs
// x solvers), a row per slave node sorted along the pair's mean tangent:
// its position along that tangent [m], tributary length [m], pressure and
// shear [Pa] (nodal force over tributary length times thickness, as in the
// VTU files; the shear along the tangent tau of doc/scenes.md's signs);
// <stem>-face.gp and, drawn by gnuplot, <stem>-face.png (a row of two
// panels per pair: pressure, shear, in mm and MPa). A solver that failed
// is left out. On a closed curve (a pin in its bore) the position folds:
// it is a projection, not an arc length.

#ifndef fuzzycontact_output_contact_face_plot_h
#define fuzzycontact_output_contact_face_plot_h

#include <fuzzycontact/output/contact_report.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/study/contact_scene.h>

#include <string>

namespace FuzzyContact
{
  /** The data file's text (see above). */
  std::string
  contact_face_data(const ContactCase &c, const ContactScene &bodies);

  /**
   * Queues the data, script and picture in @p output; false (no PNG) if
   * gnuplot could not draw it, @p message then says why.
   */
  bool
  add_contact_face_plot(OutputFiles        &output,
                        const ContactCase  &c,
                        const ContactScene &bodies,
                        const std::string  &label,
                        std::string        &message);
} // namespace FuzzyContact

#endif
