/*
 * files.c — writing a whole file safely (rayscad_file_write) and the
 * library's version.  The temporary file comes from the io module's
 * io_temp_beside, like every other output, so permissions and clean-up are
 * the same for text, images and meshes.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "../io/temp_file.h"
#include "../io/versions.h"
#include "rayscad_internal.h"

rayscad_status rayscad_file_write(const char *path, const void *data, size_t len, char *err,
                                  size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    char tmp[4096];
    if (io_temp_beside(path, tmp, sizeof tmp, err, errlen) != 0) return RAYSCAD_ERROR;
    FILE *f = fopen(tmp, "wb");
    int bad = !f || fwrite(data, 1, len, f) != len;
    int saved = errno;
    if (f && fclose(f) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    if (bad) {
        rayscad_say(err, errlen, "cannot write '%s': %s", path, strerror(saved));
        unlink(tmp);
        return RAYSCAD_ERROR;
    }
    return io_temp_commit(tmp, path, err, errlen) == 0 ? RAYSCAD_OK : RAYSCAD_ERROR;
}

const char *rayscad_version(void)
{
    return RAYSCAD_VERSION_STRING;
}

void rayscad_library_info(char *buf, size_t len)
{
    snprintf(buf, len,
             "OpenImageIO: %s\nOpenMesh: %s\nlib3mf: %s\nFreeType: %s\nHarfBuzz: %s\n"
             "fontconfig: %s\nfonts: %d\ncairo: %s\n",
             io_image_library_version(), io_openmesh_version(), io_lib3mf_version(),
             io_freetype_version(), io_harfbuzz_version(), io_fontconfig_version(), io_font_count(),
             io_cairo_version());
}
