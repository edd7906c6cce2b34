#include <glissade/base/input_error.h>
#include <glissade/io/directory_lock.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

namespace glissade
{
  DirectoryLock::DirectoryLock(const std::string &directory,
                               const std::string &entry)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
      throw InputError(entry,
                       "cannot create the output directory '" + directory +
                         "': " + error.message());
    const std::string file = directory + "/.glissade-lock";
    descriptor = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor < 0)
      throw InputError(entry,
                       "cannot write in the output directory '" + directory +
                         "': " + std::strerror(errno));
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        const int reason = errno;
        ::close(descriptor);
        descriptor = -1;
        if (reason == EWOULDBLOCK)
          throw InputError(entry,
                           "the output directory '" + directory +
                             "' is in use by another glissade run that is "
                             "still going; give this run its own directory "
                             "(--set 'Output/Directory=...')");
        throw InputError(entry,
                         "cannot lock the output directory '" + directory +
                           "': " + std::strerror(reason));
      }
  }



  DirectoryLock::~DirectoryLock()
  {
    if (descriptor >= 0)
      ::close(descriptor); // releases the lock
  }
} // namespace glissade
