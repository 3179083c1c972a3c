/*
 * test_pdf.c — the PDF page of a 2D export (src/io/pdf.cpp) and its page
 * test: openscad 2021.01's limits worked out by hand (a millimetre is
 * 2.8346 points; a point is past the page when its coordinate, truncated
 * to whole points, is more than 595 x 842 from the corner, or more than
 * half that from the centre; each path's first point is not tested), the
 * same bytes for the same paths (no dates), and writes that fail with a
 * message and leave no file.  tests/rayscad/test_region.c and
 * tests/cli/openscad_flags.sh compare the pages with openscad's own.
 */
#include "../../src/io/pdf.h"
#include "../../src/io/region_export.h"

#include <criterion/criterion.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];

static void make_dir(void)
{
    snprintf(dir, sizeof dir, "/tmp/rayscad-pdf-XXXXXX");
    cr_assert_not_null(mkdtemp(dir));
}

static void remove_dir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    cr_assert_eq(system(cmd), 0);
}

TestSuite(pdf, .init = make_dir, .fini = remove_dir);

/* A rectangle [x0, x1] x [y0, y1], counter-clockwise from (x0, y0). */
static int fits_rect(double x0, double y0, double x1, double y1)
{
    const double pts[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    const int start[2] = {0, 4};
    return io_region_fits_pdf_page(pts, start, 1);
}

Test(pdf, fits_page_from_the_corner)
{
    /* 210 mm is 595.27 points, truncated 595: on the page */
    cr_expect(fits_rect(0, 0, 210, 10));
    cr_expect(!fits_rect(0, 0, 211, 10));   /* 598.1 */
    cr_expect(fits_rect(0, 0, 10, 297.1));  /* 842.2 → 842 */
    cr_expect(!fits_rect(0, 0, 10, 297.4)); /* 843.0 */
    /* min y of -0.5 still rounds up to 0: the corner layout */
    cr_expect(fits_rect(0, -0.5, 200, 10));
}

Test(pdf, fits_page_from_the_centre)
{
    /* min x < 0: the origin is the page's centre, 297.5 x 421 each way */
    cr_expect(fits_rect(-105, -1, -104, 0));    /* 297.6 → 297 */
    cr_expect(!fits_rect(-105.3, -1, -104, 0)); /* 298.5 → 298 */
    cr_expect(fits_rect(-1, -148.5, 0, 0));     /* 420.9 */
    cr_expect(!fits_rect(-1, -149, 0, 0));      /* 422.4 */
    /* 211 mm wide from -1: the centre layout, past the right edge */
    cr_expect(!fits_rect(-1, 0, 210, 10));
}

Test(pdf, fits_page_skips_first_points)
{
    /* openscad tests every point but each path's first */
    const double pts[3][2] = {{105.7, 0}, {-52.1, 91.1}, {-52.1, -91.1}};
    const int start[2] = {0, 3};
    cr_expect(io_region_fits_pdf_page(pts, start, 1));
    const double turned[3][2] = {{-52.1, 91.1}, {105.7, 0}, {-52.1, -91.1}};
    cr_expect(!io_region_fits_pdf_page(turned, start, 1));
    cr_expect(io_region_fits_pdf_page(NULL, NULL, 0));
}

static long file_size(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fclose(f);
    return n;
}

static unsigned char *read_all(const char *path, long *n)
{
    *n = file_size(path);
    if (*n < 0) return NULL;
    FILE *f = fopen(path, "rb");
    unsigned char *b = malloc((size_t)*n + 1);
    cr_assert(f && b);
    cr_assert_eq(fread(b, 1, (size_t)*n, f), (size_t)*n);
    fclose(f);
    b[*n] = 0;
    return b;
}

/* s among the n bytes of b (a PDF holds NULs in its streams). */
static int contains(const unsigned char *b, long n, const char *s)
{
    size_t k = strlen(s);
    for (long i = 0; i + (long)k <= n; i++)
        if (memcmp(b + i, s, k) == 0) return 1;
    return 0;
}

/* A square with a hole: the same paths twice give the same bytes (no
 * dates in the file), a PDF of one A4 page with rayscad as its creator. */
Test(pdf, write_is_reproducible)
{
    const double pts[8][2] = {{0, 0}, {20, 0}, {20, 20}, {0, 20},
                              {5, 5}, {5, 15}, {15, 15}, {15, 5}};
    const int start[3] = {0, 4, 8};
    char a[128], b[128], err[256];
    snprintf(a, sizeof a, "%s/a.pdf", dir);
    snprintf(b, sizeof b, "%s/b.PDF", dir);
    cr_assert_eq(io_region_format_of(b), IO_REGION_PDF);
    cr_assert_eq(io_region_write(a, IO_REGION_PDF, pts, start, 2, err, sizeof err), 0, "%s", err);
    cr_assert_eq(io_region_write(b, IO_REGION_PDF, pts, start, 2, err, sizeof err), 0, "%s", err);
    long na, nb;
    unsigned char *da = read_all(a, &na), *db = read_all(b, &nb);
    cr_assert(da && db);
    cr_expect(na == nb && memcmp(da, db, (size_t)na) == 0, "two writes differ");
    cr_expect(na > 5 && memcmp(da, "%PDF-", 5) == 0);
    cr_expect(contains(da, na, "/MediaBox [ 0 0 595 842 ]"));
    cr_expect(contains(da, na, "/Creator (rayscad "));
    cr_expect(!contains(da, na, "/CreationDate"));
    cr_expect(!contains(da, na, "/ModDate"));
    free(da);
    free(db);
}

/* A full disk: cairo's writes fail, the message says why. */
Test(pdf, write_to_full_disk)
{
    FILE *f = fopen("/dev/full", "wb");
    if (!f) cr_skip_test("no /dev/full");
    const double pts[3][2] = {{0, 0}, {10, 0}, {0, 10}};
    const int start[2] = {0, 3};
    char err[256] = "";
    int rc = io_pdf_write(f, pts, start, 1, err, sizeof err);
    /* the last block may still sit in the stream's buffer */
    int flushed = fflush(f);
    fclose(f);
    cr_expect(rc != 0 || flushed != 0, "a full disk went unnoticed");
    if (rc != 0) cr_expect_not_null(strstr(err, "No space left on device"), "%s", err);
}

/* No folder to write in, or a point that is not finite: an error naming
 * the path, and no file, temporary or not. */
Test(pdf, write_fails_cleanly)
{
    const double pts[3][2] = {{0, 0}, {10, 0}, {0, 10}};
    const int start[2] = {0, 3};
    char path[128], err[256] = "";
    snprintf(path, sizeof path, "%s/none/x.pdf", dir);
    cr_expect_eq(io_region_write(path, IO_REGION_PDF, pts, start, 1, err, sizeof err), -1);
    cr_expect(strncmp(err, path, strlen(path)) == 0, "%s", err);
    const double bad[3][2] = {{0, 0}, {1.0 / 0.0, 0}, {0, 10}};
    snprintf(path, sizeof path, "%s/bad.pdf", dir);
    cr_expect_eq(io_region_write(path, IO_REGION_PDF, bad, start, 1, err, sizeof err), -1);
    cr_expect_not_null(strstr(err, "not finite"), "%s", err);
    DIR *d = opendir(dir);
    cr_assert_not_null(d);
    struct dirent *e;
    int files = 0;
    while ((e = readdir(d)))
        if (e->d_name[0] != '.' || strlen(e->d_name) > 2) files++;
    closedir(d);
    cr_expect_eq(files, 0, "a failed write left a file in %s", dir);
}
