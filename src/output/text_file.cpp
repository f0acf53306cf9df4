#include "output/text_file.hpp"

#include <cerrno>
#include <system_error>

namespace camouflet {

TextFile::TextFile(const std::filesystem::path& path, Mode mode) : path_(path) {
  file_ = std::fopen(path.c_str(), mode == Mode::write ? "w" : "a");
  if (!file_) fail("cannot open for writing");
  // A buffer larger than any line: each flushed line then reaches the file in
  // one write(), so a killed run never leaves half a gauge row.
  std::setvbuf(file_, nullptr, _IOFBF, std::size_t{1} << 20);
}

TextFile::~TextFile() {
  if (file_) std::fclose(file_);
}

void TextFile::fail(const char* what) const {
  const int err = errno != 0 ? errno : EIO;
  throw std::filesystem::filesystem_error(what, path_, std::error_code(err, std::generic_category()));
}

void TextFile::write(std::string_view text) {
  errno = 0;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) fail("cannot write");
}

void TextFile::flush() {
  errno = 0;
  if (std::fflush(file_) != 0) fail("cannot write");
}

void TextFile::close() {
  if (!file_) return;
  errno = 0;
  const bool ok = std::fflush(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok || !closed) fail("cannot write");
}

void write_file_atomically(const std::filesystem::path& path, std::string_view text) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    TextFile f(tmp);
    f.write(text);
    f.close();
  }
  std::filesystem::rename(tmp, path);  // throws filesystem_error on failure
}

}  // namespace camouflet
