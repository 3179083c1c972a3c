/*
 * options.c — parse the command line.  Every flag takes its value either as
 * --flag=value or as the next argument; -o and -D also as -oFILE / -Dname=v.
 * Numbers are parsed strictly: trailing junk, NaN and infinities are usage
 * errors, never silently zero.  Also here: the defaults of the limits that
 * depend on the machine, and the error line that names the memory limit.
 */
#include "options.h"
#include "options_parse.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const char cli_usage[] =
    "usage: rayscad FILE.scad -o OUTPUT [-o OUTPUT ...] [options]\n"
    "       rayscad FILE.scad --measure [--json] [-o OUTPUT] [options]\n"
    "       rayscad FILE.scad [options]    a window on the model (no -o), reloaded\n"
    "                                      when a file it read changes; ? lists its keys\n"
    "\n"
    "Renders an OpenSCAD file by ray casting its CSG tree with interval lists.\n"
    "OUTPUT's extension (or --export-format) picks the format: .png .jpg .tif\n"
    ".exr (images), .pov (a POV-Ray scene), .stl .off .obj .ply .amf .3mf (a\n"
    "mesh of the model, top-level objects unioned; STL as text unless binstl),\n"
    ".svg .dxf .pdf (a 2D model, as openscad writes them),\n"
    ".echo (the ECHO and WARNING lines, as openscad -o x.echo writes them),\n"
    ".csg (the evaluated tree, as openscad -o x.csg writes it), .ast (the parsed\n"
    "file printed back) and .term (the CSG term text), as openscad writes them.\n"
    "FILE '-' reads the model from the standard input, OUTPUT '-' writes to the\n"
    "standard output.\n"
    "\n"
    "  -o FILE                 output file, repeatable: one run writes them all\n"
    "                          (none, and no --measure: the viewer's window)\n"
    "  -D name=value           override a top-level variable (repeatable)\n"
    "  --camera=tx,ty,tz,rx,ry,rz,dist   gimbal camera, as OpenSCAD\n"
    "  --camera=ex,ey,ez,cx,cy,cz        eye and centre camera, as OpenSCAD\n"
    "  --imgsize=W,H           image size in pixels (default 512,512; the\n"
    "                          viewer's window 800,600)\n"
    "  --stats                 the viewer: a line per frame drawn on stderr\n"
    "  --section=a,b,c,d       cut the model by the plane ax+by+cz=d, taking away\n"
    "                          the side where ax+by+cz > d (cut faces coloured)\n"
    "  --projection=p|o        perspective (default) or orthographic\n"
    "  --viewall               fit the model in view\n"
    "  --autocenter            centre the model in view\n"
    "  --colorscheme=NAME      OpenSCAD colour scheme (default Cornfield)\n"
    "  --samples N             N×N stratified samples per pixel (default 1)\n"
    "  --threads N             worker threads (default: all cores)\n"
    "  --facets=MODE           round primitives: auto (default; smooth unless\n"
    "                          $fn <= 16), smooth (exact), openscad (its facets)\n"
    "  --max-recursion N       nested calls before an error (default 10000)\n"
    "  --max-steps N           calls and loop values before an error (default 1e9)\n"
    "  --max-list N            elements of one list (default 2^26)\n"
    "  --max-string N          bytes of one string (default 2^28)\n"
    "  --max-pixels N          pixels of a rendered image (default 2^28; a side\n"
    "                          has at most 65536 whatever N is)\n"
    "  --max-intervals N       intervals one list may hold while a ray is traced\n"
    "                          (default 2^20)\n"
    "  --max-mesh-cells N      cells of the mesh and --measure grid (default 2^32)\n"
    "  --max-memory SIZE       data memory (heap and thread stacks), bytes or with\n"
    "                          K, M, G, T (default: 3/4 of RAM, plus 1G for the\n"
    "                          evaluator's stack and the workers' stacks)\n";

const char cli_usage_light[] =
    "\n"
    "Light model (opt-in; without these and $rs_ variables the image looks like\n"
    "OpenSCAD's preview):\n"
    "  --shadows               shadows from the preview's key light\n"
    "  --light=x,y,z[,r[,i]]   a light at x,y,z (radius r > 0: soft shadows;\n"
    "                          intensity i, default 1); repeatable, up to 16\n"
    "  --light-samples N       N×N shadow rays per area light (default 4)\n"
    "  --bounces N             mirror/refraction depth limit (default 4)\n"
    "  --refract[=IOR]         transparent solids refract (default IOR 1.5)\n"
    "  --aperture A            thin-lens diameter (depth of field)\n"
    "  --focus F               focal distance (default: to the model's centre)\n"
    "  --xray[=A]              every surface at most A opaque (default 0.25)\n"
    "  --absorb[=T]            thickness mode: alpha is the opacity of T mm of\n"
    "                          the solid, Beer-Lambert (default T = 10)\n"
    "  --seed N                jitter seed (default 0)\n"
    "  --path-trace[=N]        path-traced quality mode: interreflection, N\n"
    "                          samples per pixel (default 64)\n"
    "\n"
    "Meshes (.stl .off .obj .ply) and measurement:\n"
    "  --mesh-size H           grid spacing in model units (default: each far-apart\n"
    "                          part's longest side / 128, finer for thin walls)\n"
    "  --ascii                 text STL or PLY (STL is text by default, as\n"
    "                          openscad's; PLY binary; OFF, OBJ are text)\n"
    "  --mesh-tolerance D      simplify the mesh to within about D of the exact\n"
    "                          surface: flat faces become a few triangles,\n"
    "                          curves as few as D allows, sharp edges and\n"
    "                          corners stay (default: the deviation OpenSCAD's\n"
    "                          facets would give the model's round parts at\n"
    "                          their $fn/$fa/$fs, else 1e-4 of its size, for a\n"
    "                          contour of up to 2^19 triangles; 0: the contour\n"
    "                          unsimplified)\n"
    "  --decimate TOL          the older name of --mesh-tolerance (0: no\n"
    "                          simplification)\n"
    "  --measure               print volume, surface area, bounding box and centre\n"
    "                          of mass, integrated exactly from rays: exact for\n"
    "                          plane faces, curved ones to --measure-tolerance\n"
    "                          (with --mesh-size and no --measure-tolerance:\n"
    "                          on the mesh's grid)\n"
    "  --measure-tolerance T   relative error of --measure on curved surfaces\n"
    "                          (default 1e-6 of the bounding sphere's)\n"
    "  --json                  the same as JSON on stdout (implies --measure)\n";

int cli_parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v)) return -1;
    *out = v;
    return 0;
}

int cli_parse_int(const char *s, long lo, long hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v < lo || v > hi) return -1;
    *out = (int)v;
    return 0;
}

/* A size in bytes: a number (fractions allowed) and an optional K, M, G or
 * T (powers of 1024, either case).  At least 1 MiB: the program's own data
 * is about 0.7 MiB before it reads a file, so less is surely a slip. */
static int parse_size(const char *s, unsigned long long *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || errno == ERANGE || !isfinite(v)) return -1;
    if (*end) { /* not NUL, so strchr cannot match the string's end */
        static const char units[] = "KMGT";
        const char *u = strchr(units, toupper((unsigned char)*end));
        if (!u || end[1] != '\0') return -1;
        v = ldexp(v, 10 * (int)(u - units + 1));
    }
    if (!(v >= 1 << 20) || v >= 0x1p63) return -1;
    *out = (unsigned long long)v;
    return 0;
}

/* Split a comma list of up to max numbers; returns the count, or -1. */
static int parse_numbers(const char *s, double *v, int max)
{
    char buf[512];
    if (strlen(s) >= sizeof buf) return -1;
    strcpy(buf, s);
    int n = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (n == max || cli_parse_double(tok, &v[n]) != 0) return -1;
        n++;
    }
    return n;
}

int cli_flag_value(int argc, char **argv, int *i, const char *name, const char **value)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0) return 0;
    if (a[n] == '=') {
        *value = a + n + 1;
        return 1;
    }
    if (a[n] != '\0') return 0;
    if (*i + 1 >= argc) return -1;
    *value = argv[++*i];
    return 1;
}

int cli_optional_value(const char *a, const char *name, const char **value)
{
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0 || (a[n] != '\0' && a[n] != '=')) return 0;
    *value = a[n] == '=' ? a + n + 1 : NULL;
    return 1;
}

/* The light-model flags.  Returns 1 when argv[*i] was one (consumed), 0
 * when it is not, -1 with a message in err for a bad value. */
static int parse_optics(int argc, char **argv, int *i, rayscad_render_options *p, char *err,
                        size_t errlen)
{
    const char *a = argv[*i], *val = NULL;
    double x;
    int r;
    if (strcmp(a, "--shadows") == 0) {
        p->shadows = 1;
        return 1;
    }
    if (cli_optional_value(a, "--xray", &val)) {
        p->xray = 0.25;
        if (val && (cli_parse_double(val, &p->xray) != 0 || !(p->xray > 0) || p->xray > 1)) {
            snprintf(err, errlen, "--xray expects an opacity in (0, 1], got '%s'", val);
            return -1;
        }
        return 1;
    }
    if (cli_optional_value(a, "--absorb", &val)) {
        p->absorb = 10;
        if (val && (cli_parse_double(val, &p->absorb) != 0 || !(p->absorb > 0))) {
            snprintf(err, errlen, "--absorb expects a thickness > 0, got '%s'", val);
            return -1;
        }
        return 1;
    }
    if (cli_optional_value(a, "--path-trace", &val)) {
        p->path_trace = 64;
        if (val && cli_parse_int(val, 1, 1000000, &p->path_trace) != 0) {
            snprintf(err, errlen, "--path-trace expects samples per pixel in 1..1000000, got '%s'",
                     val);
            return -1;
        }
        return 1;
    }
    if (cli_optional_value(a, "--refract", &val)) {
        p->ior = 1.5;
        if (val && (cli_parse_double(val, &p->ior) != 0 || !(p->ior >= 1) || p->ior > 10)) {
            snprintf(err, errlen, "--refract expects an index of refraction in 1..10, got '%s'",
                     val);
            return -1;
        }
        return 1;
    }
    if ((r = cli_flag_value(argc, argv, i, "--light", &val)) != 0) {
        double v[5] = {0, 0, 0, 0, 1};
        int n = r > 0 ? parse_numbers(val, v, 5) : -1;
        if (n < 3 || v[3] < 0 || !(v[4] > 0) || p->nlights == RAYSCAD_MAX_LIGHTS) {
            snprintf(err, errlen,
                     "--light expects x,y,z[,radius[,intensity]] (radius >= 0, intensity > 0, "
                     "at most %d lights), got '%s'",
                     RAYSCAD_MAX_LIGHTS, r > 0 ? val : "");
            return -1;
        }
        rayscad_light *L = &p->lights[p->nlights++];
        for (int k = 0; k < 3; k++)
            L->pos[k] = v[k];
        L->radius = v[3];
        L->intensity = v[4];
        return 1;
    }
    static const struct {
        const char *name;
        int is_int;
        double lo, hi;
    } numeric[] = {{"--light-samples", 1, 1, 16},
                   {"--bounces", 1, 1, 64},
                   {"--aperture", 0, 0, 1e9},
                   {"--focus", 0, 0, 1e9},
                   {"--seed", 1, 0, 2147483647}};
    for (size_t k = 0; k < sizeof numeric / sizeof *numeric; k++) {
        r = cli_flag_value(argc, argv, i, numeric[k].name, &val);
        if (r == 0) continue;
        if (r < 0 || cli_parse_double(val, &x) != 0 || x < numeric[k].lo || x > numeric[k].hi ||
            (numeric[k].is_int && x != floor(x)) || (k == 3 && !(x > 0))) {
            snprintf(err, errlen, "%s expects a %s in %g..%g, got '%s'", numeric[k].name,
                     numeric[k].is_int ? "whole number" : "number", numeric[k].lo, numeric[k].hi,
                     r < 0 ? "" : val);
            return -1;
        }
        switch (k) {
        case 0:
            p->light_samples = (int)x;
            break;
        case 1:
            p->bounces = (int)x;
            break;
        case 2:
            p->aperture = x;
            break;
        case 3:
            p->focus = x;
            break;
        default:
            p->seed = (unsigned)x;
            break;
        }
        return 1;
    }
    return 0;
}

int cli_options_parse(int argc, char **argv, cli_options *o, char *err, size_t errlen)
{
    memset(o, 0, sizeof *o);
    o->width = 512;
    o->height = 512;
    o->samples = 1;
    o->colorscheme = "Cornfield";
    o->view.kind = RAYSCAD_CAMERA_DEFAULT;
    o->check_parameters = 1;
    o->mesh_tolerance = -1; /* the model's own (mesh_output.c) */

    static const char *const valued[] = {"-o",
                                         "-D",
                                         "--camera",
                                         "--imgsize",
                                         "--projection",
                                         "--colorscheme",
                                         "--samples",
                                         "--threads",
                                         "--facets",
                                         "--mesh-size",
                                         "--decimate",
                                         "--mesh-tolerance",
                                         "--measure-tolerance",
                                         "--max-recursion",
                                         "--max-steps",
                                         "--max-list",
                                         "--max-string",
                                         "--max-pixels",
                                         "--max-intervals",
                                         "--max-mesh-cells",
                                         "--max-memory",
                                         "--section"};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = NULL;
        const char *flag = NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            o->help = 1;
            continue;
        }
        if (strcmp(a, "--version") == 0 || strcmp(a, "-v") == 0) {
            o->version = 1;
            continue;
        }
        if (strcmp(a, "--viewall") == 0) {
            o->view.viewall = 1;
            continue;
        }
        if (strcmp(a, "--autocenter") == 0) {
            o->view.autocenter = 1;
            continue;
        }
        if (strcmp(a, "--ascii") == 0) {
            o->ascii = 1;
            continue;
        }
        if (strcmp(a, "--stats") == 0) {
            o->stats = 1;
            continue;
        }
        if (strcmp(a, "--measure") == 0 || strcmp(a, "--json") == 0) {
            o->measure = 1;
            o->json |= a[2] == 'j';
            continue;
        }
        int optic = parse_optics(argc, argv, &i, &o->optics, err, errlen);
        if (optic < 0) return -1;
        if (optic > 0) continue;
        int oscad = cli_parse_openscad_flag(argc, argv, &i, o, err, errlen);
        if (oscad < 0) return -1;
        if (oscad > 0) continue;
        if ((a[0] == '-' && (a[1] == 'o' || a[1] == 'D') && a[2] != '\0' && a[2] != '=')) {
            flag = a[1] == 'o' ? "-o" : "-D";
            val = a + 2;
        }
        for (size_t k = 0; !flag && k < sizeof valued / sizeof *valued; k++) {
            int r = cli_flag_value(argc, argv, &i, valued[k], &val);
            if (r < 0) {
                snprintf(err, errlen, "%s needs a value", valued[k]);
                return -1;
            }
            if (r > 0) flag = valued[k];
        }
        if (!flag) {
            if (a[0] == '-' && a[1] != '\0') { /* "-" alone: the standard input */
                snprintf(err, errlen, "unknown option '%s'", a);
                return -1;
            }
            if (o->input) {
                snprintf(err, errlen, "more than one input file ('%s' and '%s')", o->input, a);
                return -1;
            }
            o->input = a;
            continue;
        }
        if (strcmp(flag, "-o") == 0) {
            if (cli_options_add_output(o, val, err, errlen) != 0) return -1;
        } else if (strcmp(flag, "-D") == 0) {
            if (o->define_count == CLI_MAX_DEFINES || !strchr(val, '=')) {
                snprintf(err, errlen, "-D expects name=value (at most %d of them)",
                         CLI_MAX_DEFINES);
                return -1;
            }
            o->defines[o->define_count++] = val;
        } else if (strcmp(flag, "--camera") == 0) {
            int n = parse_numbers(val, o->view.v, 7);
            if (n != 6 && n != 7) {
                snprintf(err, errlen,
                         "--camera expects 7 numbers (tx,ty,tz,rx,ry,rz,dist) or 6 "
                         "(ex,ey,ez,cx,cy,cz), got '%s'",
                         val);
                return -1;
            }
            o->view.kind = n == 7 ? RAYSCAD_CAMERA_GIMBAL : RAYSCAD_CAMERA_EYE;
        } else if (strcmp(flag, "--imgsize") == 0) {
            /* Any size an int holds; main refuses what --max-pixels does not
             * allow, as a limit rather than as a usage error. */
            double wh[2];
            if (parse_numbers(val, wh, 2) != 2 || wh[0] < 1 || wh[1] < 1 || wh[0] > 2147483647 ||
                wh[1] > 2147483647 || wh[0] != floor(wh[0]) || wh[1] != floor(wh[1])) {
                snprintf(err, errlen, "--imgsize expects W,H, whole numbers >= 1, got '%s'", val);
                return -1;
            }
            o->width = (int)wh[0];
            o->height = (int)wh[1];
            o->imgsize_given = 1;
        } else if (strcmp(flag, "--section") == 0) {
            double *p = o->optics.section;
            if (parse_numbers(val, p, 4) != 4 || !(p[0] != 0 || p[1] != 0 || p[2] != 0) ||
                !isfinite(p[0] + p[1] + p[2] + p[3])) {
                snprintf(err, errlen,
                         "--section expects a,b,c,d: the plane ax+by+cz=d, (a,b,c) not 0, got "
                         "'%s'",
                         val);
                return -1;
            }
        } else if (strcmp(flag, "--projection") == 0) {
            if (val[0] == 'o' || val[0] == 'O')
                o->view.ortho = 1;
            else if (val[0] == 'p' || val[0] == 'P')
                o->view.ortho = 0;
            else {
                snprintf(err, errlen, "--projection expects p or o, got '%s'", val);
                return -1;
            }
        } else if (strcmp(flag, "--facets") == 0) {
            if (strcmp(val, "auto") == 0)
                o->facets = RAYSCAD_FACETS_AUTO;
            else if (strcmp(val, "smooth") == 0)
                o->facets = RAYSCAD_FACETS_SMOOTH;
            else if (strcmp(val, "openscad") == 0)
                o->facets = RAYSCAD_FACETS_OPENSCAD;
            else {
                snprintf(err, errlen, "--facets expects auto, smooth or openscad, got '%s'", val);
                return -1;
            }
        } else if (strcmp(flag, "--mesh-size") == 0) {
            if (cli_parse_double(val, &o->mesh_size) != 0 || !(o->mesh_size > 0)) {
                snprintf(err, errlen, "--mesh-size expects a grid spacing > 0, got '%s'", val);
                return -1;
            }
        } else if (strcmp(flag, "--measure-tolerance") == 0) {
            if (cli_parse_double(val, &o->measure_tolerance) != 0 ||
                !(o->measure_tolerance > 0 && o->measure_tolerance < 1)) {
                snprintf(err, errlen, "--measure-tolerance expects a fraction in (0, 1), got '%s'",
                         val);
                return -1;
            }
        } else if (strcmp(flag, "--mesh-tolerance") == 0) {
            if (cli_parse_double(val, &o->mesh_tolerance) != 0 || !(o->mesh_tolerance >= 0)) {
                snprintf(err, errlen, "--mesh-tolerance expects a distance >= 0, got '%s'", val);
                return -1;
            }
        } else if (strcmp(flag, "--decimate") == 0) { /* --mesh-tolerance, as it was */
            if (cli_parse_double(val, &o->mesh_tolerance) != 0 || !(o->mesh_tolerance >= 0)) {
                snprintf(err, errlen, "--decimate expects a tolerance >= 0, got '%s'", val);
                return -1;
            }
        } else if (strcmp(flag, "--colorscheme") == 0) {
            o->colorscheme = val;
        } else if (strcmp(flag, "--samples") == 0) {
            if (cli_parse_int(val, 1, 64, &o->samples) != 0) {
                snprintf(err, errlen, "--samples expects a whole number in 1..64, got '%s'", val);
                return -1;
            }
        } else if (!strcmp(flag, "--max-memory")) {
            if (parse_size(val, &o->max_memory) != 0) {
                snprintf(err, errlen,
                         "--max-memory expects a size of at least 1M, in bytes or with a K, M, "
                         "G or T suffix, got '%s'",
                         val);
                return -1;
            }
            o->max_memory_given = 1;
        } else if (!strncmp(flag, "--max-", 6)) {
            /* counted limits: whole numbers from 1 up to what the field
             * holds (--max-intervals: a span stack of 4N spans still counts
             * in an int32) */
            static const struct {
                const char *name;
                double hi;
            } limits[] = {{"--max-recursion", 2147483647.0},
                          {"--max-steps", 1e15},
                          {"--max-list", 2147483647.0},
                          {"--max-string", 2147483647.0},
                          {"--max-pixels", 1e15},
                          {"--max-intervals", 1 << 28},
                          {"--max-mesh-cells", 1e15}};
            size_t k = 0;
            while (strcmp(limits[k].name, flag) != 0)
                k++;
            double x;
            if (cli_parse_double(val, &x) != 0 || !(x >= 1) || x != floor(x) || x > limits[k].hi) {
                snprintf(err, errlen, "%s expects a whole number in 1..%.0f, got '%s'", flag,
                         limits[k].hi, val);
                return -1;
            }
            switch (k) {
            case 0:
                o->max_recursion = (int)x;
                break;
            case 1:
                o->max_steps = (long)x;
                break;
            case 2:
                o->max_list = (int)x;
                break;
            case 3:
                o->max_string = (int)x;
                break;
            case 4:
                o->max_pixels = (long long)x;
                break;
            case 5:
                o->max_intervals = (int)x;
                break;
            default:
                o->max_mesh_cells = (long long)x;
                break;
            }
        } else if (strcmp(flag, "--threads") == 0) {
            if (cli_parse_int(val, 0, 1024, &o->threads) != 0) {
                snprintf(err, errlen, "--threads expects a whole number in 0..1024, got '%s'", val);
                return -1;
            }
        }
    }
    if (o->help || o->version || o->info) return 0;
    if (!o->input) {
        snprintf(err, errlen, "no input file");
        return -1;
    }
    if (!o->output_count && !o->measure) { /* as openscad FILE opens its window */
        if (!strcmp(o->input, "-")) {
            snprintf(err, errlen,
                     "no output file (-o): the viewer needs a file to watch, not "
                     "the standard input");
            return -1;
        }
        o->viewer = 1;
        if (!o->imgsize_given) {
            o->width = 800;
            o->height = 600;
        }
    }
    return 0;
}
