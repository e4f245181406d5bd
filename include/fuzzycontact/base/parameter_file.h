// What deal.II's ParameterHandler does not check in a parameter file, and
// its messages in the user's words.
//
// - A key set twice in the same subsection: ParameterHandler keeps the last
//   value without a word; scan_parameter_text() refuses it, naming both
//   lines.
// - The subsections a file opens at its top level ("Fuzzy parameter P1.E"),
//   so that a study can learn names from the subsections alone.
// - A mandatory key that is not set: ParameterHandler names it in its
//   internal, mangled form (Component_20P1.lower_20left_20corner);
//   check_mandatory_entries() names the key and its subsection as the file
//   spells them.
// - Any other ParameterHandler message with a mangled path is given back in
//   the file's spelling (user_message()).

#ifndef fuzzycontact_base_parameter_file_h
#define fuzzycontact_base_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace Input
  {
    using namespace dealii;

    /** What a parameter file contains, as far as its lines tell. */
    struct ParameterFileStructure
    {
      /** The names of the top-level subsections, in the order they open. */
      std::vector<std::string> top_level_subsections;
    };

    /**
     * Scans the text of a parameter file the way ParameterHandler reads it
     * (comments, continued lines, 'subsection', 'end', 'set'). Throws,
     * naming @p filename, both lines and the key, if a key is set twice in
     * the same subsection.
     */
    ParameterFileStructure
    scan_parameter_text(const std::string &text, const std::string &filename);

    /**
     * A ParameterHandler path such as "Component_20P1.lower_20left_20corner"
     * in the user's spelling: {"Component P1", "lower left corner"}.
     */
    std::vector<std::string>
    demangle_path(const std::string &mangled);

    /**
     * Throws, naming @p filename and every mandatory key that is not set
     * with its subsection, if ParameterHandler @p prm (after parsing) has
     * such keys.
     */
    void
    check_mandatory_entries(const ParameterHandler &prm,
                            const std::string      &filename);

    /**
     * @p message with every mangled ParameterHandler name in it
     * (Component_20P1) given back in the user's spelling (Component P1).
     */
    std::string
    demangle_message(const std::string &message);
  } // namespace Input
} // namespace FuzzyContact

#endif
