/*
 * test_amf_3mf.c — io_amf_read and io_3mf_read on the committed files
 * (tests/models/data, tests/hostile/data; run from the repository root):
 * counts and volumes of what they read, the welding of per-corner vertices,
 * objects kept side by side, and the exact warnings of malformed files.
 */
#include "../../src/io/io.h"

#include <criterion/criterion.h>

#include <stdlib.h>
#include <string.h>

/* Signed volume of triangles counter-clockwise seen from outside. */
static double volume(const float *v, const int32_t *t, int nt)
{
    double sum = 0;
    for (int i = 0; i < nt; i++) {
        const float *a = v + 3 * t[3 * i], *b = v + 3 * t[3 * i + 1], *c = v + 3 * t[3 * i + 2];
        sum += a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
               a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
               a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0]);
    }
    return sum / 6;
}

typedef int (*reader)(const char *, float **, int *, int32_t **, int *, char *, size_t);

typedef struct read_result {
    int rc, nv, nt;
    double vol;
    char msg[2048];
} read_result;

static read_result read_with(reader r, const char *path)
{
    read_result out;
    float *v = NULL;
    int32_t *t = NULL;
    out.rc = r(path, &v, &out.nv, &t, &out.nt, out.msg, sizeof out.msg);
    out.vol = out.nt > 0 ? volume(v, t, out.nt) : 0;
    free(v);
    free(t);
    return out;
}

Test(io_amf, two_objects_side_by_side_and_welded)
{
    /* two boxes, 10x8x6 and 8x8x8, in one zipped AMF; the second has a
     * vertex per triangle corner (36), welded to its 8 corners */
    read_result r = read_with(io_amf_read, "tests/models/data/two_boxes.amf");
    cr_assert_eq(r.rc, 0, "%s", r.msg);
    cr_expect_str_empty(r.msg);
    cr_expect_eq(r.nv, 16);
    cr_expect_eq(r.nt, 24);
    cr_expect_float_eq(r.vol, 480.0 + 512.0, 1e-3);
}

Test(io_amf, openscad_export_reads_closed)
{
    read_result r = read_with(io_amf_read, "tests/models/data/part.amf");
    cr_assert_eq(r.rc, 0, "%s", r.msg);
    cr_expect_str_empty(r.msg);
    cr_expect_gt(r.nt, 0);
    cr_expect_gt(r.vol, 0);
}

Test(io_amf, malformed_files_say_why)
{
    read_result r = read_with(io_amf_read, "tests/hostile/data/not_a_number.amf");
    cr_expect_eq(r.rc, -1);
    cr_expect_str_eq(r.msg, "Failed to parse file 'tests/hostile/data/not_a_number.amf': line 4: "
                            "<y> '1e' is not a number");
    r = read_with(io_amf_read, "tests/hostile/data/index_out_of_range.amf");
    cr_expect_eq(r.rc, -1);
    cr_expect_str_eq(r.msg, "Failed to parse file 'tests/hostile/data/index_out_of_range.amf': "
                            "line 9: triangle vertex index 7 is out of range (the object has "
                            "4 vertices so far)");
    r = read_with(io_amf_read, "tests/hostile/data/zip_two_entries.amf");
    cr_expect_eq(r.rc, -1);
    cr_expect_str_eq(r.msg, "Can't read file 'zip_two_entries.amf' from zipped AMF "
                            "'tests/hostile/data/zip_two_entries.amf'\n"
                            "Can't open import file 'tests/hostile/data/zip_two_entries.amf'");
    r = read_with(io_amf_read, "tests/hostile/data/deep.amf");
    cr_expect_eq(r.rc, -1);
    cr_expect(!strncmp(r.msg, "Failed to parse file 'tests/hostile/data/deep.amf': line 1: ", 60),
              "%s", r.msg);
}

Test(io_amf, parse_error_keeps_complete_objects)
{
    /* as in 2021.01: the first object (a tetrahedron) is kept */
    read_result r = read_with(io_amf_read, "tests/hostile/data/second_object_broken.amf");
    cr_expect_eq(r.rc, 0);
    cr_expect_eq(r.nt, 4);
    cr_expect_float_eq(r.vol, 1.0 / 6, 1e-6);
    cr_expect_str_eq(r.msg, "Failed to parse file 'tests/hostile/data/second_object_broken.amf': "
                            "line 20: <v3> 'x' is not an index");
}

Test(io_amf, empty_element_hides_the_rest_as_in_2021_01)
{
    read_result r = read_with(io_amf_read, "tests/hostile/data/empty_element.amf");
    cr_expect_eq(r.rc, 0);
    cr_expect_eq(r.nt, 0);
    cr_expect(!strncmp(r.msg,
                       "note: 'tests/hostile/data/empty_element.amf' line 3: nothing after "
                       "the empty element <metadata/> is read",
                       99),
              "%s", r.msg);
}

Test(io_3mf, mesh_objects_without_build_transforms)
{
    /* two boxes, 8x8x3 and 2x2x12; the build item's move is ignored */
    read_result r = read_with(io_3mf_read, "tests/models/data/post.3mf");
    cr_assert_eq(r.rc, 0, "%s", r.msg);
    cr_expect_str_empty(r.msg);
    cr_expect_eq(r.nv, 16);
    cr_expect_eq(r.nt, 24);
    cr_expect_float_eq(r.vol, 192.0 + 48.0, 1e-3);
}

Test(io_3mf, unreadable_files_say_why)
{
    read_result r = read_with(io_3mf_read, "tests/hostile/data/garbage.3mf");
    cr_expect_eq(r.rc, -1);
    cr_expect(!strncmp(r.msg, "Could not read file 'tests/hostile/data/garbage.3mf'", 52), "%s",
              r.msg);
    r = read_with(io_3mf_read, "tests/hostile/data/index_out_of_range.3mf");
    cr_expect_eq(r.rc, -1);
    r = read_with(io_3mf_read, "tests/hostile/data/nowhere.3mf");
    cr_expect_eq(r.rc, -1);
    cr_expect(r.nv == 0 && r.nt == 0);
}
