#include "AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lkapp
{
namespace
{
std::string failure(const std::string& path, int code)
{
  return "cannot write '" + path + "': " + std::strerror(code);
}

/// The file a write to `path` replaces: the target of a link, or `path`.
std::string resolved(const std::string& path)
{
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode))
    return path;
  char buffer[PATH_MAX];
  return ::realpath(path.c_str(), buffer) ? std::string(buffer) : path;
}

/// Removes what runs killed by SIGKILL (the out-of-memory killer, on a large
/// CT) left of their writes to `target`: its temporary files
/// (temporaryPathBeside's names) whose process no longer exists. Those of a
/// live process, another user's, or another file are left alone.
void removeStaleTemporaries(const std::string& target)
{
  const FileNameParts p = splitFileName(target);
  const std::string prefix = "." + p.stem + ".partial-";
  DIR* dir = ::opendir(p.folder.empty() ? "." : p.folder.c_str());
  if (!dir)
    return;
  std::vector<std::string> stale;
  while (const dirent* entry = ::readdir(dir))
  {
    const std::string name = entry->d_name;
    if (name.size() <= prefix.size() + p.extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - p.extension.size(), p.extension.size(), p.extension) != 0)
      continue;
    // PID-N between the prefix and the extension.
    const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - p.extension.size());
    const auto dash = middle.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == middle.size() ||
      middle.find_first_not_of("0123456789-") != std::string::npos || middle.find('-', dash + 1) != std::string::npos)
      continue;
    const long pid = std::strtol(middle.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid() || pid > INT_MAX)
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      stale.push_back(p.folder + name);
  }
  ::closedir(dir);
  for (const std::string& path : stale)
    ::unlink(path.c_str());
}

/// Empty when `target` may be replaced, otherwise the reason.
std::string refusal(const std::string& path, const std::string& target)
{
  struct stat st;
  if (::stat(target.c_str(), &st) != 0)
    return {}; // a new file; the folder's permissions decide
  if (S_ISDIR(st.st_mode))
    return failure(path, EISDIR);
  if (!S_ISREG(st.st_mode))
    return "cannot write '" + path + "': it is not a regular file";
  if (::access(target.c_str(), W_OK) != 0)
    return failure(path, errno);
  return {};
}
} // namespace

FileNameParts splitFileName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  FileNameParts parts;
  parts.folder = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.find_last_of('.');
  parts.stem = dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
  parts.extension = dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
  return parts;
}

std::string temporaryPathBeside(const std::string& path)
{
  static std::atomic<unsigned> counter{ 0 };
  // The extension stays last: some writers (vtkPLYWriter) append their own
  // to a name without it.
  const FileNameParts p = splitFileName(path);
  return p.folder + "." + p.stem + ".partial-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
    p.extension;
}

bool commitTemporaryFile(const std::string& temporary, const std::string& path, std::string& error)
{
  const std::string target = resolved(path);
  auto fail = [&](int code) {
    ::unlink(temporary.c_str());
    error = failure(path, code);
    return false;
  };
  error = refusal(path, target);
  if (!error.empty())
  {
    ::unlink(temporary.c_str());
    return false;
  }
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    return fail(errno);
  struct stat old;
  if (::stat(target.c_str(), &old) == 0)
    ::fchmod(fd, old.st_mode & 07777); // the permissions the user gave the file
  if (::fsync(fd) != 0)
  {
    const int code = errno;
    ::close(fd);
    return fail(code);
  }
  if (::close(fd) != 0)
    return fail(errno);
  if (::rename(temporary.c_str(), target.c_str()) != 0)
    return fail(errno);
  removeStaleTemporaries(target);
  return true;
}

bool writeFileAtomically(const std::string& path, const std::string& contents, std::string& error)
{
  const std::string target = resolved(path);
  error = refusal(path, target);
  if (!error.empty())
    return false;
  const std::string temporary = temporaryPathBeside(target);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    error = failure(path, errno);
    return false;
  }
  const char* at = contents.data();
  std::size_t left = contents.size();
  while (left > 0)
  {
    const ssize_t n = ::write(fd, at, left);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
    {
      const int code = n < 0 ? errno : EIO;
      ::close(fd);
      ::unlink(temporary.c_str());
      error = failure(path, code);
      return false;
    }
    at += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0)
  {
    const int code = errno;
    ::unlink(temporary.c_str());
    error = failure(path, code);
    return false;
  }
  return commitTemporaryFile(temporary, path, error);
}

} // namespace lkapp
