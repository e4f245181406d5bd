// Writing results: every file of a run is kept in memory until the run has
// succeeded, then written atomically (to a temporary file in the same folder,
// renamed over the target), so that a failed run leaves no files and a
// finished one never leaves a half-written file.

#ifndef fuzzycontact_output_output_files_h
#define fuzzycontact_output_output_files_h

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

    /** Creates the folder and writes every queued file atomically. */
    void
    write_all() const;

    const std::string &
    directory() const;

  private:
    std::string                        directory_;
    std::map<std::string, std::string> files_;
  };

} // namespace FuzzyContact

#endif
