// Small helpers for reading and checking parameter values. Every check
// throws an ExcMessage whose text starts with the name of what was being
// read ("Component P1, zone root: E"), so that a user knows which line of
// the parameter file to fix.

#ifndef fuzzycontact_base_input_h
#define fuzzycontact_base_input_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace Input
  {
    using namespace dealii;

    /**
     * Reads a strictly formatted floating point number (no trailing
     * characters, finite). @p what names the parameter in the message.
     */
    double
    to_double(const std::string &text, const std::string &what);

    /**
     * Reads a comma-separated list of numbers; if @p expected_size is not
     * zero the list must have exactly that many entries.
     */
    std::vector<double>
    to_doubles(const std::string &text,
               const std::string &what,
               const unsigned int expected_size = 0);

    /**
     * Reads a comma-separated list of names. Each name must be non-empty,
     * made of letters, digits, '_' and '-', and appear only once.
     */
    std::vector<std::string>
    to_names(const std::string &text, const std::string &what);

    /** Throws unless @p value is finite and strictly positive. */
    double
    positive(const double value, const std::string &what);

    /** Throws unless @p value is finite and not negative. */
    double
    non_negative(const double value, const std::string &what);

    /** Throws unless @p value is finite. */
    double
    finite(const double value, const std::string &what);

    /**
     * Returns @p path if it is absolute, otherwise @p path read relative to
     * the folder of @p reference_file (the parameter file that names it).
     */
    std::string
    resolve_relative_to(const std::string &path,
                        const std::string &reference_file);

    /**
     * The whole content of a text file; throws naming the file if it does
     * not exist, is a folder or cannot be read.
     */
    std::string
    read_text_file(const std::string &filename);

    /**
     * Parses @p text (the content of @p filename) into @p prm; a message
     * of ParameterHandler is rethrown in the file's spelling of the names.
     */
    void
    parse_text(ParameterHandler  &prm,
               const std::string &text,
               const std::string &filename,
               const bool         skip_undefined);

    /**
     * Parses the parameter file @p filename into @p prm strictly: an unknown
     * key or subsection, a key set twice, a malformed value and a missing
     * mandatory entry all throw.
     */
    void
    parse_strictly(ParameterHandler &prm, const std::string &filename);

    /**
     * Parses a parameter file whose subsections depend on names listed in
     * it (components, zones, fuzzy parameters, ...). Each pass declares what
     * @p declare knows so far into a fresh ParameterHandler and parses
     * @p text skipping the rest; @p learn_names reads the name lists and
     * returns true if they changed. When nothing changes any more, a last
     * pass declares everything and parses strictly (unknown keys, keys set
     * twice, malformed values and missing mandatory entries throw), and
     * @p parse reads it.
     */
    void
    parse_in_passes(const std::string                             &text,
                    const std::string                             &source_name,
                    const std::function<void(ParameterHandler &)> &declare,
                    const std::function<bool(ParameterHandler &)> &learn_names,
                    const std::function<void(ParameterHandler &)> &parse);

    /**
     * The user-facing text of a deal.II exception: its "additional
     * information" only (no source location or stack trace), on one line.
     */
    std::string
    message_of(const ExceptionBase &exception);
  } // namespace Input
} // namespace FuzzyContact

#endif
