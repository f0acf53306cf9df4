#pragma once
// A text file written through stdio whose every failure (folder missing, disk
// full, permission) throws std::filesystem::filesystem_error naming the path:
// the command line turns that into exit code 3 (docs/exit-codes.md), never a
// crash or a silently truncated result.
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace camouflet {

class TextFile {
 public:
  enum class Mode { write, append };
  TextFile(const std::filesystem::path& path, Mode mode = Mode::write);
  ~TextFile();
  TextFile(const TextFile&) = delete;
  TextFile& operator=(const TextFile&) = delete;

  void write(std::string_view text);
  void flush();  // to the operating system (a killed run keeps every flushed line)
  void close();  // flush and close; throws on failure
  const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] void fail(const char* what) const;
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
};

// Writes `text` to `path` through a temporary file and a rename, so that a
// reader never sees a half-written file (used for .pvd and summary.json).
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace camouflet
