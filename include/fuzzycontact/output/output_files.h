// Writing results: every file of a run is kept in memory until the run has
// succeeded, then written as a set: into a new folder beside the output
// folder (".<name>.new-<pid>"), which is then swapped with the old one in a
// single rename (Linux's RENAME_EXCHANGE; elsewhere two renames). A reader
// sees the old set or the new one, never a mix; a failed run leaves no
// files; the staging folders of a killed run are removed by the next run
// that writes beside them. Results with a NaN or an infinity, or computed
// after a LAPACK error (base/lapack_errors.h), are refused, not written.

#ifndef fuzzycontact_output_output_files_h
#define fuzzycontact_output_output_files_h

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace FuzzyContact
{
  /**
   * Writes @p content to @p filename atomically, creating its folder.
   */
  void
  write_file_atomically(const std::string &filename,
                        const std::string &content);

  /**
   * The files a program will write into one folder.
   */
  class OutputFiles
  {
  public:
    explicit OutputFiles(const std::string &directory);

    /** Queues a file (replacing one of the same name). */
    void
    add(const std::string &filename, std::string content);

    /**
     * Queues a JSON file. Its numbers are checked here: a NaN or an
     * infinity among them is refused by write_all(), while its nulls are
     * the writer's own "no value" (n/a: a level without bounds, a proof
     * without an exact value), not a NaN that the dump turned into null.
     */
    void
    add_json(const std::string &filename, const nlohmann::json &content);

    /**
     * Writes every queued file, replacing the whole folder at once (see
     * the top of this file). Throws, writing nothing, if a text file holds
     * a NaN or an infinity or if a LAPACK error is pending.
     */
    void
    write_all() const;

    const std::string &
    directory() const;

  private:
    std::string                        directory_;
    std::map<std::string, std::string> files_;
    // The files queued as JSON (their nulls are values): whether a number
    // of theirs is not finite.
    std::map<std::string, bool> json_non_finite_;
  };

} // namespace FuzzyContact

#endif
