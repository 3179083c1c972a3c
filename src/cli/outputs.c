/*
 * outputs.c — see outputs.h.
 */
#define _DEFAULT_SOURCE /* mkstemps */
#include "outputs.h"

#include "../../include/rayscad.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The formats openscad 2021.01 names that rayscad does not write, and why. */
static const struct {
    const char *name, *why;
} not_written[] = {
    {"nef3", "nef3 is CGAL's own format, which rayscad has no use for and does not write"},
    {"nefdbg", "nefdbg is CGAL's own debugging format, which rayscad does not write"},
};

/* The extension of path (after the last '.' of its last component),
 * lower-cased into buf; "" when none. */
static const char *extension(const char *path, char *buf, size_t len)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    buf[0] = '\0';
    if (!dot || (slash && dot < slash) || dot == path || strlen(dot + 1) >= len) return buf;
    size_t i = 0;
    for (const char *p = dot + 1; *p; p++)
        buf[i++] = (char)tolower((unsigned char)*p);
    buf[i] = '\0';
    return buf;
}

int cli_output_resolve(const char *path, const char *fmt, int ascii, cli_output *out, char *err,
                       size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->path = path;
    char name[16], probe[32];
    if (fmt) {
        snprintf(name, sizeof name, "%s", fmt);
        for (char *p = name; *p; p++)
            *p = (char)tolower((unsigned char)*p);
        if (strlen(fmt) >= sizeof name) name[0] = '\0';
    } else {
        extension(strcmp(path, "-") ? path : "", name, sizeof name);
        if (!name[0]) {
            snprintf(err, errlen,
                     "Either add a valid suffix or specify one using the --export-format option.");
            return 1;
        }
    }
    out->ascii = ascii;
    const char *ext = name;
    if (!strcmp(name, "asciistl") || !strcmp(name, "binstl")) {
        ext = "stl";
        out->ascii = ascii || name[0] == 'a';
        out->kind = OUTPUT_MESH;
    } else if (!strcmp(name, "echo")) {
        out->kind = OUTPUT_ECHO;
    } else if (!strcmp(name, "csg")) {
        out->kind = OUTPUT_CSG;
    } else if (!strcmp(name, "ast")) {
        out->kind = OUTPUT_AST;
    } else if (!strcmp(name, "term")) {
        out->kind = OUTPUT_TERM;
    } else if (!strcmp(name, "pov")) {
        out->kind = OUTPUT_POV;
    } else {
        snprintf(probe, sizeof probe, "x.%s", name);
        if (name[0] && rayscad_region_format_supported(probe)) {
            out->kind = OUTPUT_2D;
        } else if (name[0] && rayscad_mesh_format_supported(probe)) {
            out->kind = OUTPUT_MESH;
            /* openscad 2021.01 writes STL as text unless asked for binstl */
            out->ascii = ascii || !strcmp(name, "stl");
        } else if (name[0] && rayscad_image_format_supported(probe)) {
            out->kind = OUTPUT_IMAGE;
        } else {
            for (size_t k = 0; k < sizeof not_written / sizeof *not_written; k++)
                if (!strcmp(name, not_written[k].name)) {
                    snprintf(err, errlen, "%s: %s", path, not_written[k].why);
                    return 1;
                }
            if (fmt)
                snprintf(err, errlen,
                         "Unknown --export-format option '%s'.  Use -h to list available options.",
                         fmt);
            else
                snprintf(err, errlen,
                         "cannot tell the output format from '%s' (use .png .jpg .tif .exr .stl "
                         ".off .obj .ply .amf .3mf .svg .dxf .pdf .pov .echo .csg .ast or .term, "
                         "or "
                         "--export-format)",
                         path);
            return 1;
        }
    }
    snprintf(out->ext, sizeof out->ext, "%s", ext);
    return 0;
}

const char *cli_output_frame_path(const char *path, int frame, char *buf, size_t len)
{
    if (!strcmp(path, "-")) return path;
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) dot = path + strlen(path);
    snprintf(buf, len, "%.*s%05d%s", (int)(dot - path), path, frame, dot);
    return buf;
}

int cli_output_begin(cli_output *out, const char *path, char *err, size_t errlen)
{
    char ext[16];
    out->temporary = strcmp(path, "-") == 0 || strcmp(extension(path, ext, sizeof ext), out->ext);
    if (!out->temporary) {
        if (strlen(path) >= sizeof out->write) {
            snprintf(err, errlen, "%s: the path is too long", path);
            return -1;
        }
        strcpy(out->write, path);
        return 0;
    }
    /* Beside the target (one file system: a rename), or for the standard
     * output in TMPDIR.  The name is reserved by mkstemps and written over
     * by the writer's own rename. */
    const char *dir = getenv("TMPDIR");
    int n;
    if (strcmp(path, "-"))
        n = snprintf(out->write, sizeof out->write, "%s.rayscad-XXXXXX.%s", path, out->ext);
    else
        n = snprintf(out->write, sizeof out->write, "%s/rayscad-XXXXXX.%s",
                     dir && *dir ? dir : "/tmp", out->ext);
    if (n < 0 || (size_t)n >= sizeof out->write) {
        snprintf(err, errlen, "%s: the path is too long", path);
        return -1;
    }
    int fd = mkstemps(out->write, (int)strlen(out->ext) + 1);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create a temporary file: %s", out->write,
                 strerror(errno));
        return -1;
    }
    /* mkstemps made it private; the file is the user's as any other */
    mode_t mask = umask(0);
    umask(mask);
    int rc = fchmod(fd, 0666 & ~mask);
    if (rc != 0) {
        snprintf(err, errlen, "%s: %s", out->write, strerror(errno));
        remove(out->write);
    }
    close(fd);
    return rc;
}

static int copy_to_stdout(const char *from, char *err, size_t errlen)
{
    FILE *f = fopen(from, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", from, strerror(errno));
        return -1;
    }
    char buf[65536];
    size_t n;
    int rc = 0;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        if (fwrite(buf, 1, n, stdout) != n) rc = -1;
    if (ferror(f)) rc = -1;
    fclose(f);
    if (fflush(stdout) != 0) rc = -1;
    if (rc) snprintf(err, errlen, "cannot write to the standard output: %s", strerror(errno));
    return rc;
}

int cli_output_finish(cli_output *out, const char *path, int ok, char *err, size_t errlen)
{
    if (!out->temporary) return 0;
    int rc = 0;
    if (ok && strcmp(path, "-") == 0) {
        rc = copy_to_stdout(out->write, err, errlen);
    } else if (ok && rename(out->write, path) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        rc = -1;
    }
    if (!ok || rc != 0 || strcmp(path, "-") == 0) remove(out->write);
    return rc;
}

int cli_output_write(cli_output *out, const char *path, cli_writer write, void *ctx, char *err,
                     size_t errlen)
{
    if (cli_output_begin(out, path, err, errlen) != 0) return -1;
    int ok = write(ctx, out->write, err, errlen) == 0;
    if (cli_output_finish(out, path, ok, err, errlen) != 0) ok = 0;
    return ok ? 0 : -1;
}
