/*
 * scene_of.h — the scene of an OpenSCAD source through the public API, for
 * the tests of tests/rayscad (include after criterion and rayscad.h).
 */
#ifndef TESTS_RAYSCAD_SCENE_OF_H
#define TESTS_RAYSCAD_SCENE_OF_H

/* The scene of source src (its file's view in *file, which may be NULL). */
static inline rayscad_scene *scene_of(const char *src, rayscad_file_view *file)
{
    rayscad_model *model;
    cr_assert_eq(rayscad_model_load_string("t.scad", src, NULL, &model), RAYSCAD_OK, "%s", src);
    if (file) rayscad_model_file_view(model, file);
    rayscad_scene *scene;
    cr_assert_eq(rayscad_scene_new(model, &scene, NULL, 0), RAYSCAD_OK);
    rayscad_model_free(model);
    return scene;
}

#endif
