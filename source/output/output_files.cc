#include <fuzzycontact/output/output_files.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace FuzzyContact
{
  using namespace dealii;

  void
  write_file_atomically(const std::string &filename, const std::string &content)
  {
    namespace fs = std::filesystem;
    const fs::path target(filename);
    if (target.has_parent_path())
      fs::create_directories(target.parent_path());
    const fs::path temporary =
      target.string() + ".tmp-" + std::to_string(::getpid());
    {
      std::ofstream out(temporary, std::ios::binary);
      AssertThrow(out.good(),
                  ExcMessage("Cannot write the file <" + temporary.string() +
                             ">."));
      out << content;
      out.flush();
      AssertThrow(out.good(),
                  ExcMessage("Writing <" + temporary.string() + "> failed."));
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error)
      {
        fs::remove(temporary);
        AssertThrow(false,
                    ExcMessage("Cannot move the result into <" + filename +
                               ">: " + error.message()));
      }
  }


  OutputFiles::OutputFiles(const std::string &directory)
      : directory_(directory)
  {
  }


  void
  OutputFiles::add(const std::string &filename, std::string content)
  {
    files_[filename] = std::move(content);
  }


  void
  OutputFiles::write_all() const
  {
    for (const auto &[name, content] : files_)
      write_file_atomically((std::filesystem::path(directory_) / name).string(),
                            content);
  }


  const std::string &
  OutputFiles::directory() const
  {
    return directory_;
  }


} // namespace FuzzyContact
