/*
 * image.c — rendering a scene (src/render) and reading and writing images
 * (src/io's OpenImageIO adapter, loaded on first use).
 */
#include <string.h>

#include "../io/io.h"
#include "../render/overlay.h"
#include "../render/render.h"
#include "rayscad_internal.h"

void rayscad_render_options_default(rayscad_render_options *o)
{
    memset(o, 0, sizeof *o);
    o->width = 512;
    o->height = 512;
    o->samples = 1;
    render_colors_by_name("Cornfield", &o->colors);
}

rayscad_status rayscad_render(const rayscad_scene *s, const rayscad_camera *cam,
                              const rayscad_render_options *o, float *rgba, char *err,
                              size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    int rc = render_image(s->s, cam, o, rgba, err, errlen);
    if (rc == 0) rc = render_overlays(s->s, cam, o, rgba, err, errlen);
    return rc == 0                         ? RAYSCAD_OK
           : rc == RAYSCAD_ERROR_INTERVALS ? RAYSCAD_ERROR_INTERVALS
           : rc == RAYSCAD_CANCELLED       ? RAYSCAD_CANCELLED
                                           : RAYSCAD_ERROR;
}

rayscad_status rayscad_pov_export(const rayscad_scene *s, const rayscad_camera *cam,
                                  const rayscad_render_options *o, char **text, size_t *len,
                                  char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    size_t n;
    if (render_pov_export(s->s, cam, o, text, &n, err, errlen) != 0) return RAYSCAD_ERROR;
    if (len) *len = n;
    return RAYSCAD_OK;
}

int rayscad_image_format_supported(const char *path)
{
    return io_image_format_supported(path);
}

rayscad_status rayscad_image_write(const char *path, int width, int height, int channels,
                                   const float *pixels, char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    return io_image_write(path, width, height, channels, pixels, err, errlen) == 0 ? RAYSCAD_OK
                                                                                   : RAYSCAD_ERROR;
}

rayscad_status rayscad_image_read(const char *path, int *width, int *height, int *channels,
                                  float **pixels, char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    return io_image_read(path, width, height, channels, pixels, err, errlen) == 0 ? RAYSCAD_OK
                                                                                  : RAYSCAD_ERROR;
}

rayscad_status rayscad_image_load(char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    return io_image_load(err, errlen) == 0 ? RAYSCAD_OK : RAYSCAD_ERROR;
}
