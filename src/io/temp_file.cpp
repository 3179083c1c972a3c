/*
 * temp_file.cpp — see temp_file.h.  mkstemps in the target's own directory
 * keeps the final rename on one file system, so it is atomic; mkstemps
 * creates the file 0600, so the mode is set afterwards.  Plain C++ with C
 * linkage: nothing here throws.
 */
#include "temp_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

extern "C" int io_temp_beside(const char *path, char *tmp, size_t tmplen, char *err, size_t errlen)
{
    const char *slash = std::strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = std::strrchr(base, '.');
    const char *ext = dot && dot != base ? dot : "";
    int n = std::snprintf(tmp, tmplen, "%.*s.%.*s.XXXXXX%s", (int)(base - path), path,
                          (int)(ext[0] ? ext - base : (long)std::strlen(base)), base, ext);
    if (n < 0 || (size_t)n >= tmplen) {
        std::snprintf(err, errlen, "%s: path too long", path);
        return -1;
    }
    int fd = mkstemps(tmp, (int)std::strlen(ext));
    if (fd < 0) {
        std::snprintf(err, errlen, "%s: cannot create a temporary file: %s", path,
                      std::strerror(errno));
        return -1;
    }
    struct stat st;
    mode_t mode;
    if (stat(path, &st) == 0) {
        mode = st.st_mode & 07777;
    } else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    fchmod(fd, mode);
    close(fd);
    return 0;
}

extern "C" int io_temp_commit(const char *tmp, const char *path, char *err, size_t errlen)
{
    if (std::rename(tmp, path) != 0) {
        std::snprintf(err, errlen, "%s: cannot rename the finished file into place: %s", path,
                      std::strerror(errno));
        std::remove(tmp);
        return -1;
    }
    return 0;
}
