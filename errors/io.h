// Checked writes of files (results, charts' inputs, scratch meshes). A write that fails — a full
// file system, the file-size limit of `ulimit -f`, a quota — must end the command with an I/O
// error naming the file and the reason, never leave a result or a scratch mesh with a piece
// missing for the next step to misread (a truncated scene mesh was reported as bad input by the
// mesh reader, a full -o folder as a success without its chart; issue 49).
//
//   write_file(path, [&](std::ostream& out) { out << ...; });  // IoError(path, reason)
//   check_complete_file(path, "$End");  // a file another library wrote (gmsh)
//
// Header-only and free of deal.II and MPI, like errors/errors.h (IoError is here, not there, so
// that the many files including errors.h need not know it).
#pragma once

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>

namespace gearstiff
{
namespace io_detail
{
// strerror's text as the rest of a message: "No space left on device" → "no space left on device".
inline std::string error_text(int error_number)
{
  std::string text = std::strerror(error_number);
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z' &&
      !(text.size() > 1 && text[1] >= 'A' && text[1] <= 'Z'))
    text[0] = static_cast<char>(text[0] - 'A' + 'a');
  return text;
}

// Free space, in kB, of the file system holding `path` (or its folder); -1 when unknown.
inline long long free_kilobytes(const std::string& path)
{
  struct statvfs fs
  {
  };
  const std::string folder = path.substr(0, path.find_last_of('/') + 1);
  if (statvfs(path.c_str(), &fs) != 0 && statvfs(folder.empty() ? "." : folder.c_str(), &fs) != 0)
    return -1;
  return static_cast<long long>(fs.f_bavail) * static_cast<long long>(fs.f_frsize) / 1024;
}

// Size of `path` in bytes; -1 when it does not exist.
inline long long file_bytes(const std::string& path)
{
  struct stat status
  {
  };
  return stat(path.c_str(), &status) == 0 ? static_cast<long long>(status.st_size) : -1;
}
} // namespace io_detail

// A file that could not be written whole (a full file system, the file-size limit): `path` and
// why (write_failure_reason). `place` (empty unless app/ set it) says where the path lives for the
// user ("-o out", "TMPDIR (/tmp)"), and `path` is then relative to it. The command prints it as one
// line and exits 1; it is neither bad input nor a failed numerical method.
class IoError : public std::runtime_error
{
public:
  IoError(const std::string& path, const std::string& reason, const std::string& place = "")
      : std::runtime_error((place.empty() ? "" : place + ": ") + "cannot write '" + path +
                           "': " + reason),
        path_text(path), reason_text(reason), place_text(place)
  {
  }

  const std::string& path() const { return path_text; }
  const std::string& reason() const { return reason_text; }
  const std::string& place() const { return place_text; }

private:
  std::string path_text;
  std::string reason_text;
  std::string place_text;
};

// Why a write into `path` failed, as the rest of a message. `error_number` (errno right after the
// failure, 0: unknown) is trusted when it names a lack of room; otherwise the file system is
// asked, since errno may have been overwritten after a stream's failed write: the file-size limit
// reached by the file (EFBIG) or no space left (ENOSPC).
inline std::string write_failure_reason(const std::string& path, int error_number)
{
  const long long bytes = io_detail::file_bytes(path);
  struct rlimit limit
  {
  };
  const bool at_size_limit = getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
                             limit.rlim_cur != RLIM_INFINITY && bytes >= 0 &&
                             static_cast<unsigned long long>(bytes) >= limit.rlim_cur;
  if (error_number == EFBIG || (at_size_limit && error_number != ENOSPC))
    return "file size limit reached (ulimit -f: " + std::to_string(limit.rlim_cur / 1024) +
           " kB per file)";
  // A full file system still reports a block or so free to a write that needs more. The free
  // space is stated only then: a writer that removed its partial file (matplotlib) leaves more.
  const long long free_kb = io_detail::free_kilobytes(path);
  const bool full = free_kb >= 0 && free_kb < 64;
  if (error_number == ENOSPC || full)
    return io_detail::error_text(ENOSPC) +
           (full ? " (" + std::to_string(free_kb) + " kB free)" : "");
  if (error_number != 0)
    return io_detail::error_text(error_number);
  return "the write failed";
}

// Writes `path` through `write` and checks that every byte reached the file: IoError(path,
// reason) when it cannot be created or a write or the close fails (an exception `write` throws
// once the stream has failed — deal.II's ExcIO — is that IoError too).
inline void write_file(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  errno = 0;
  std::ofstream out(path);
  if (!out)
    throw IoError(path, errno != 0 ? io_detail::error_text(errno) : "cannot create the file");
  try
  {
    write(out);
  }
  catch (...)
  {
    if (!out.fail())
      throw;
    throw IoError(path, write_failure_reason(path, errno));
  }
  if (!out.fail())
    out.close();
  if (out.fail())
    throw IoError(path, write_failure_reason(path, errno));
}

// A file another library wrote without telling of a failed write (gmsh::write): complete only if
// its last line starts with `end_marker` ("$End" for a .msh). IoError(path, reason, with the size
// reached: more than that is needed) otherwise.
inline void check_complete_file(const std::string& path, const std::string& end_marker)
{
  std::ifstream in(path, std::ios::binary);
  const long long bytes = io_detail::file_bytes(path);
  std::string last_line;
  if (in && bytes > 0)
  {
    const long long tail = std::min<long long>(bytes, 256);
    in.seekg(bytes - tail);
    std::string text(static_cast<std::size_t>(tail), '\0');
    in.read(text.data(), tail);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
      text.pop_back();
    last_line = text.substr(text.find_last_of('\n') + 1);
  }
  if (last_line.rfind(end_marker, 0) == 0)
    return;
  if (bytes < 0)
    throw IoError(path, "the file was not created");
  throw IoError(path, write_failure_reason(path, 0) + "; the file is incomplete at " +
                          std::to_string(std::max(bytes, 0LL) / 1024) + " kB, more is needed");
}
} // namespace gearstiff
