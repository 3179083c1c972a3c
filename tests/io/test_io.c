/*
 * test_io.c — images through OpenImageIO: round trips per format, the bytes
 * as an independent reader (oiiotool --dumpdata) sees them, straight alpha,
 * linear EXR, and writes that fail without leaving a file behind.
 */
#include "../../src/io/io.h"

#include <criterion/criterion.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { W = 7, H = 5 };

static char dir[64];

static void make_dir(void)
{
    snprintf(dir, sizeof dir, "/tmp/rayscad-io-XXXXXX");
    cr_assert_not_null(mkdtemp(dir));
}

static void remove_dir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) { /* a leftover in /tmp is harmless */
    }
}

TestSuite(io_image, .init = make_dir, .fini = remove_dir);

/* A deterministic test pattern: every channel a different value, some on
 * exact byte values, some between them, and the ends 0 and 1. */
static void pattern(float *px, int channels)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int c = 0; c < channels; c++) {
                float v = (float)((x * 37 + y * 91 + c * 53) % 256) / 255.0f;
                if ((x + y) % 3 == 0) v += 0.3f / 255.0f; /* rounds down */
                if ((x + y) % 3 == 1) v += 0.7f / 255.0f; /* rounds up */
                if (x == 0 && y == 0) v = 0;
                if (x == W - 1 && y == H - 1) v = 1;
                if (v > 1) v = 1;
                px[(y * W + x) * channels + c] = v;
            }
}

static int file_exists(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0;
}

/* Entries in dir other than . and .. */
static int dir_entries(void)
{
    DIR *d = opendir(dir);
    cr_assert_not_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

static void roundtrip_8bit(const char *name, int channels)
{
    char path[128], err[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    float px[W * H * 4];
    pattern(px, channels);
    cr_assert_eq(io_image_write(path, W, H, channels, px, err, sizeof err), 0, "%s", err);
    int w, h, ch;
    float *back = NULL;
    cr_assert_eq(io_image_read(path, &w, &h, &ch, &back, err, sizeof err), 0, "%s", err);
    cr_assert(w == W && h == H && ch == channels, "%dx%d, %d channels", w, h, ch);
    for (int i = 0; i < W * H * channels; i++) {
        float expect = floorf(px[i] * 255.0f + 0.5f) / 255.0f; /* rounded to nearest */
        cr_expect(fabsf(back[i] - expect) < 1e-6f, "%s value %d: wrote %.5f, read %.5f (%g)", name,
                  i, px[i], back[i], expect * 255);
    }
    free(back);
    cr_expect_eq(dir_entries(), 1, "a temporary file was left behind");
}

Test(io_image, png_rgba_roundtrip)
{
    roundtrip_8bit("a.png", 4);
}
Test(io_image, png_rgb_roundtrip)
{
    roundtrip_8bit("b.png", 3);
}
Test(io_image, tiff_roundtrip)
{
    roundtrip_8bit("c.tif", 4);
}

/* Straight alpha reaches the file untouched: oiiotool, told not to
 * premultiply, prints the bytes we wrote. */
Test(io_image, png_alpha_is_straight_on_disk)
{
    if (system("command -v oiiotool >/dev/null 2>&1") != 0) cr_skip_test("no oiiotool");
    char path[128], err[256], cmd[256];
    snprintf(path, sizeof path, "%s/alpha.png", dir);
    float px[W * H * 4];
    for (int i = 0; i < W * H; i++) {
        px[i * 4 + 0] = 200 / 255.0f;
        px[i * 4 + 1] = 100 / 255.0f;
        px[i * 4 + 2] = 50 / 255.0f;
        px[i * 4 + 3] = 64 / 255.0f;
    }
    cr_assert_eq(io_image_write(path, W, H, 4, px, err, sizeof err), 0, "%s", err);
    snprintf(cmd, sizeof cmd, "oiiotool --no-autopremult --dumpdata %s 2>/dev/null", path);
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p);
    char line[256];
    int found = 0;
    while (fgets(line, sizeof line, p))
        if (strstr(line, "Pixel (3, 2):")) {
            unsigned r, g, b, a;
            char *q = strchr(line, ':');
            cr_assert(q && sscanf(q + 1, "%u %u %u %u", &r, &g, &b, &a) == 4, "%s", line);
            cr_expect(r == 200 && g == 100 && b == 50 && a == 64, "bytes %u %u %u %u", r, g, b, a);
            found = 1;
        }
    pclose(p);
    cr_expect(found, "oiiotool printed no pixel (3, 2)");
}

static float srgb_to_linear(float v)
{
    return v <= 0.04045f ? v / 12.92f : powf((v + 0.055f) / 1.055f, 2.4f);
}

/* EXR holds linear half floats: sRGB 0.5 is stored as 0.214; reading it
 * back gives the sRGB value again. */
Test(io_image, exr_is_linear_and_roundtrips)
{
    char path[128], err[256];
    snprintf(path, sizeof path, "%s/d.exr", dir);
    float px[W * H * 4];
    pattern(px, 4);
    px[0] = 0.5f;
    cr_assert_eq(io_image_write(path, W, H, 4, px, err, sizeof err), 0, "%s", err);
    int w, h, ch;
    float *back = NULL;
    cr_assert_eq(io_image_read(path, &w, &h, &ch, &back, err, sizeof err), 0, "%s", err);
    cr_assert(w == W && h == H && ch == 4);
    for (int i = 0; i < W * H * 4; i++)
        cr_expect(fabsf(back[i] - px[i]) < 2e-3f, "value %d: wrote %.5f, read %.5f", i, px[i],
                  back[i]);
    free(back);

    if (system("command -v oiiotool >/dev/null 2>&1") != 0) return;
    char cmd[256];
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata %s 2>/dev/null", path);
    FILE *p = popen(cmd, "r");
    cr_assert_not_null(p);
    char line[256];
    float r = -1;
    while (fgets(line, sizeof line, p))
        if (strstr(line, "Pixel (0, 0):")) sscanf(strchr(line, ':') + 1, "%f", &r);
    pclose(p);
    cr_expect(fabsf(r - srgb_to_linear(0.5f)) < 1e-3f, "stored %.5f, linear of 0.5 is %.5f", r,
              srgb_to_linear(0.5f));
    cr_expect(fabsf(srgb_to_linear(0.5f) - 0.21404f) < 1e-4f);
}

/* JPEG has no alpha: a 4-channel image is written as RGB. */
Test(io_image, jpeg_drops_alpha)
{
    char path[128], err[256];
    snprintf(path, sizeof path, "%s/e.jpg", dir);
    float px[W * H * 4];
    for (int i = 0; i < W * H; i++) {
        px[i * 4 + 0] = 0.8f;
        px[i * 4 + 1] = 0.4f;
        px[i * 4 + 2] = 0.2f;
        px[i * 4 + 3] = 1;
    }
    cr_assert_eq(io_image_write(path, W, H, 4, px, err, sizeof err), 0, "%s", err);
    int w, h, ch;
    float *back = NULL;
    cr_assert_eq(io_image_read(path, &w, &h, &ch, &back, err, sizeof err), 0, "%s", err);
    cr_expect(w == W && h == H && ch == 3, "%dx%d, %d channels", w, h, ch);
    cr_expect(fabsf(back[0] - 0.8f) < 0.03f && fabsf(back[1] - 0.4f) < 0.03f &&
                  fabsf(back[2] - 0.2f) < 0.03f,
              "%g %g %g", back[0], back[1], back[2]);
    free(back);
}

Test(io_image, write_into_missing_directory_fails_cleanly)
{
    char path[128], err[256] = "";
    snprintf(path, sizeof path, "%s/no/such/dir/out.png", dir);
    float px[W * H * 4];
    pattern(px, 4);
    cr_expect_eq(io_image_write(path, W, H, 4, px, err, sizeof err), -1);
    cr_expect(err[0] != 0, "no message");
    cr_expect(strstr(err, "out.png") != NULL, "message does not name the file: %s", err);
    cr_expect(!file_exists(path));
    cr_expect_eq(dir_entries(), 0);
}

/* A failed write leaves an existing file as it was. */
Test(io_image, failed_write_keeps_existing_file)
{
    char path[128], err[256];
    snprintf(path, sizeof path, "%s/keep.png", dir);
    float px[W * H * 4];
    pattern(px, 4);
    cr_assert_eq(io_image_write(path, W, H, 4, px, err, sizeof err), 0, "%s", err);
    struct stat before, after;
    cr_assert_eq(stat(path, &before), 0);
    cr_expect_eq(io_image_write(path, 0, H, 4, px, err, sizeof err), -1);
    cr_expect_eq(io_image_write(path, W, H, 2, px, err, sizeof err), -1);
    cr_assert_eq(stat(path, &after), 0);
    cr_expect(before.st_size == after.st_size && before.st_ino == after.st_ino);
    cr_expect_eq(dir_entries(), 1);
}

Test(io_image, unknown_extension_fails)
{
    char path[128], err[256] = "";
    snprintf(path, sizeof path, "%s/f.notaformat", dir);
    float px[W * H * 4];
    pattern(px, 4);
    cr_expect_eq(io_image_write(path, W, H, 4, px, err, sizeof err), -1);
    cr_expect(err[0] != 0);
    cr_expect_eq(dir_entries(), 0);
}

Test(io_image, read_missing_file_fails)
{
    int w, h, ch;
    float *px = (float *)1;
    char err[256] = "";
    cr_expect_eq(io_image_read("/nonexistent/x.png", &w, &h, &ch, &px, err, sizeof err), -1);
    cr_expect(err[0] != 0);
    cr_expect_null(px);
}

Test(io_image, format_supported)
{
    cr_expect_eq(io_image_format_supported("a.png"), 1);
    cr_expect_eq(io_image_format_supported("a.PNG"), 1);
    cr_expect_eq(io_image_format_supported("dir/a.exr"), 1);
    cr_expect_eq(io_image_format_supported("a.tif"), 1);
    cr_expect_eq(io_image_format_supported("a.jpg"), 1);
    cr_expect_eq(io_image_format_supported("a.notaformat"), 0);
    cr_expect_eq(io_image_format_supported("noextension"), 0);
    cr_expect_eq(io_image_format_supported("a.echo"), 0);
    cr_expect_eq(io_image_format_supported(NULL), 0);
}

/* A header that claims more elements than the file could hold is refused
 * before OpenMesh reserves memory for them (2e9 vertices would be ~50 GB);
 * a real file of the same form still reads. */
Test(io_mesh, implausible_header_counts_are_refused)
{
    char tmpdir[] = "/tmp/rayscad_io_XXXXXX";
    cr_assert_not_null(mkdtemp(tmpdir));
    char off[256], ply[256], ok[256];
    snprintf(off, sizeof off, "%s/huge.off", tmpdir);
    snprintf(ply, sizeof ply, "%s/huge.ply", tmpdir);
    snprintf(ok, sizeof ok, "%s/tet.off", tmpdir);
    FILE *f = fopen(off, "w");
    fputs("OFF\n2000000000 2000000000 0\n0 0 0\n", f);
    fclose(f);
    f = fopen(ply, "w");
    fputs("ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n",
          f);
    fclose(f);
    f = fopen(ok, "w");
    fputs("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n", f);
    fclose(f);
    float *v;
    int32_t *t;
    int nv, nt;
    char err[256];
    cr_expect_eq(io_mesh_read(off, &v, &nv, &t, &nt, err, sizeof err), -1);
    cr_expect(strstr(err, "element counts") != NULL, "%s", err);
    cr_expect_eq(io_mesh_read(ply, &v, &nv, &t, &nt, err, sizeof err), -1);
    cr_expect(strstr(err, "element counts") != NULL, "%s", err);
    cr_assert_eq(io_mesh_read(ok, &v, &nv, &t, &nt, err, sizeof err), 0, "%s", err);
    cr_expect_eq(nv, 4);
    cr_expect_eq(nt, 4);
    free(v);
    free(t);
    remove(off);
    remove(ply);
    remove(ok);
    rmdir(tmpdir);
}
