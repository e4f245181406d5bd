// Ranges with both ends, for the numbers of a parameter file that drive the
// cost of a run (load steps, refinements, iterations, sample counts) or
// that must be physically meaningful, and the output folder checked before
// anything is computed.
//
// Every check throws an ExcMessage that names the key as the user spells it
// (@p what, e.g. "load steps" or "Extension principle: points per
// dimension") and the accepted range.

#ifndef fuzzycontact_base_limits_h
#define fuzzycontact_base_limits_h

#include <string>

namespace FuzzyContact
{
  namespace Input
  {
    /**
     * Throws unless @p value is finite and lies in [@p lower, @p upper];
     * @p why (if not empty) is added to the message, e.g. "a physically
     * meaningful Young's modulus [Pa]".
     */
    double
    in_range(const double       value,
             const double       lower,
             const double       upper,
             const std::string &what,
             const std::string &why = "");

    /**
     * Throws unless @p value lies in [@p lower, @p upper]; returns it as
     * an unsigned int (@p lower must not be negative).
     */
    unsigned int
    integer_in_range(const long         value,
                     const long         lower,
                     const long         upper,
                     const std::string &what,
                     const std::string &why = "");

    /**
     * Checks, before a run computes anything, that the results can be
     * written to @p folder (the value of the key @p key): it is not empty,
     * not the current folder or one of its ancestors (the results are
     * swapped in as a whole folder, see output/output_files.h), not an
     * existing file, and its parent folder (or the nearest one that
     * exists) accepts a new folder. Creates nothing that stays.
     */
    void
    check_output_directory(const std::string &folder,
                           const std::string &key = "output directory");
  } // namespace Input
} // namespace FuzzyContact

#endif
