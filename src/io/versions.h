/*
 * versions.h — the versions of the libraries rayscad is built with and
 * runs against (for `rayscad --info`).  Each returns a static string;
 * "unknown" when the library cannot say.
 */
#ifndef RAYSCAD_IO_VERSIONS_H
#define RAYSCAD_IO_VERSIONS_H

#ifdef __cplusplus
extern "C" {
#endif

const char *io_openmesh_version(void);
const char *io_lib3mf_version(void);
const char *io_freetype_version(void);
const char *io_harfbuzz_version(void);
const char *io_fontconfig_version(void);
const char *io_cairo_version(void);
/* The font files fontconfig knows (text() chooses among them); -1 when it
 * cannot be asked. */
int io_font_count(void);
/* OpenImageIO's, from the image adapter (loaded for it); the load error's
 * text when it cannot load. */
const char *io_image_library_version(void);

#ifdef __cplusplus
}
#endif

#endif
