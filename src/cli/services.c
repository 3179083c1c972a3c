/*
 * services.c — scad_services for the command: meshes and images through
 * src/io.
 */
#include "services.h"

#include "../io/io.h"

static int read_mesh(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen)
{
    (void)ud;
    return io_mesh_read(path, v, nv, t, nt, err, errlen);
}

static int read_image(void *ud, const char *path, int *width, int *height, int *channels,
                      float **pixels, char *err, size_t errlen)
{
    (void)ud;
    return io_image_read(path, width, height, channels, pixels, err, errlen);
}

const scad_services *cli_services(void)
{
    static const scad_services s = {
        .read_mesh = read_mesh,
        .read_image = read_image,
    };
    return &s;
}
