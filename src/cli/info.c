/*
 * info.c — see info.h.
 */
#include "info.h"

#include "../../include/rayscad.h"

#include <stdlib.h>
#include <sys/utsname.h>
#include <unistd.h>

int cli_print_info(FILE *f)
{
    char libs[2048];
    rayscad_library_info(libs, sizeof libs);
    struct utsname u;
    const char *path = getenv("OPENSCADPATH");
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    fprintf(f, "rayscad version: %s\n", rayscad_version());
    if (uname(&u) == 0)
        fprintf(f, "System information: %s %s %s, %ld CPUs\n", u.sysname, u.release, u.machine,
                cpus);
#ifdef __VERSION__
    fprintf(f, "Compiler: %s\n", __VERSION__);
#endif
    fputs(libs, f);
    fprintf(f, "OPENSCADPATH: %s\n", path && *path ? path : "<not set>");
    fprintf(f, "Library path: /usr/share/openscad/libraries (after OPENSCADPATH)\n");
    return fflush(f) == 0 && !ferror(f) ? 0 : -1;
}
