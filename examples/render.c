/*
 * render.c — the smallest user of librayscad: OpenSCAD source text to a
 * PNG, as `rayscad -o` would draw it (OpenSCAD's default view and colours).
 *
 *   cc render.c $(pkg-config --cflags --libs rayscad) -o render
 *   ./render out.png 'difference() { cube(10, center = true); sphere(6.5); }'
 */
#include <rayscad.h>
#include <stdio.h>
#include <stdlib.h>

static void print_line(void *ud, rayscad_message_kind kind, const char *line)
{
    (void)ud, (void)kind;
    fprintf(stderr, "%s\n", line);
}

int main(int argc, char **argv)
{
    const char *src = argc > 2 ? argv[2] : "difference() { cube(10, center = true); sphere(6.5); }";
    if (argc < 2) return fprintf(stderr, "usage: render OUT.png [SCAD-SOURCE]\n"), 2;
    char err[512] = "";
    rayscad_eval_options eo = {.message = print_line};
    rayscad_model *model;
    if (rayscad_model_load_string("example.scad", src, &eo, &model) != RAYSCAD_OK) return 1;
    rayscad_view view = {.kind = RAYSCAD_CAMERA_DEFAULT};
    rayscad_model_file_view(model, &view.file);
    rayscad_scene *scene = NULL;
    rayscad_status rc = rayscad_scene_new(model, &scene, err, sizeof err);
    rayscad_model_free(model);
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    rayscad_camera cam;
    float *rgba = malloc((size_t)ro.width * ro.height * 4 * sizeof *rgba);
    if (rc == RAYSCAD_OK) rc = rgba ? RAYSCAD_OK : RAYSCAD_ERROR_MEMORY;
    if (rc == RAYSCAD_OK)
        rc = rayscad_camera_frame(scene, &view, ro.width, ro.height, &cam, err, sizeof err);
    if (rc == RAYSCAD_OK) rc = rayscad_render(scene, &cam, &ro, rgba, err, sizeof err);
    if (rc == RAYSCAD_OK)
        rc = rayscad_image_write(argv[1], ro.width, ro.height, 4, rgba, err, sizeof err);
    if (rc != RAYSCAD_OK) fprintf(stderr, "render: %s\n", err);
    free(rgba);
    rayscad_scene_free(scene);
    return rc == RAYSCAD_OK ? 0 : 1;
}
