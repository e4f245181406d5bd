// A picture drawn by gnuplot (Debian's gnuplot-nox) from a data file and a
// script, queued with a run's other files: the data and the script beside
// the PNG, so that the figure can be redrawn or restyled. gnuplot runs in a
// private temporary folder and the PNG is kept in memory, so that it is
// written with the other files, atomically (output_files.h).

#ifndef fuzzycontact_output_gnuplot_picture_h
#define fuzzycontact_output_gnuplot_picture_h

#include <fuzzycontact/output/output_files.h>

#include <string>

namespace FuzzyContact
{
  /** @p s in double quotes for a gnuplot script (inner quotes escaped). */
  std::string
  gnuplot_quoted(const std::string &s);

  /**
   * Queues <basename>.dat (@p data) and <basename>.gp (@p script, which
   * reads the data as <basename>.dat and writes <basename>.png) in @p files
   * and, if gnuplot can be run, <basename>.png. Returns false (and leaves
   * the PNG out) if gnuplot is not installed or fails; @p message then says
   * why.
   */
  bool
  add_gnuplot_picture(OutputFiles       &files,
                      const std::string &basename,
                      const std::string &data,
                      const std::string &script,
                      std::string       &message);
} // namespace FuzzyContact

#endif
