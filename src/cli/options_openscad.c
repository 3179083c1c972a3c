/*
 * options_openscad.c — the flags of `openscad --help` (2021.01) that are not
 * rayscad's own: modes, output format, messages, animation, customizer
 * parameters, dependencies.  They mean what they mean to openscad; main.c
 * says where rayscad cannot honour one.
 */
#include "options.h"
#include "options_parse.h"

#include <stdio.h>
#include <string.h>

const char cli_usage_openscad[] =
    "\n"
    "OpenSCAD's own options, meaning what they mean to openscad 2021.01:\n"
    "  --export-format FMT     every output's format: an extension, asciistl or\n"
    "                          binstl\n"
    "  --render                images as openscad's render ($preview false)\n"
    "  --preview[=throwntogether]  images as its preview (the default; thrown-\n"
    "                          together is drawn as the normal preview)\n"
    "  --animate N             N frames with $t = i/N, each output named\n"
    "                          NAME00000.EXT ...\n"
    "  -p FILE.json -P SET     customizer parameter set SET of FILE.json\n"
    "  -d FILE.deps            a Makefile rule: the outputs depend on every file\n"
    "                          read (includes, uses, imports, fonts)\n"
    "  -m MAKE                 run MAKE 'FILE' for a file to import that is missing\n"
    "  -q, --quiet             print errors only\n"
    "  --hardwarnings          stop at the first warning, as at an error (exit 1)\n"
    "  --check-parameters=true|false  warn about arguments a user module or\n"
    "                          function does not take (default true)\n"
    "  --check-parameter-ranges=true|false  warn about cube, square, circle,\n"
    "                          sphere and cylinder sizes <= 0 (default false)\n"
    "  --view=axes,crosshairs,edges,scales,wireframe  lines over images: axes\n"
    "                          (scales: with ticks), crosshairs, crease and\n"
    "                          silhouette edges; wireframe changes nothing, as\n"
    "                          in openscad's images\n"
    "  --csglimit N            accepted: interval CSG has no limit to raise\n"
    "  --debug[=WHAT]          the time each phase took, on stderr\n"
    "  --info                  what rayscad runs with (libraries, fonts)\n"
    "  -s FILE, -x FILE        openscad's deprecated names of -o\n"
    "  -h, --help              this text\n"
    "  -v, --version           the version\n"
    "\n"
    "Exit status: 0 ok, 1 the model or the output failed (a --max-* limit\n"
    "included), 2 usage error.\n";

/* openscad's boolean values for --check-parameters and friends. */
static int parse_bool(const char *s, int *out)
{
    if (!strcmp(s, "true") || !strcmp(s, "1")) {
        *out = 1;
        return 0;
    }
    if (!strcmp(s, "false") || !strcmp(s, "0")) {
        *out = 0;
        return 0;
    }
    return -1;
}

static int parse_view(const char *s, int *flags, char *err, size_t errlen)
{
    static const struct {
        const char *name;
        int bit;
    } parts[] = {{"axes", RAYSCAD_VIEW_AXES},
                 {"crosshairs", RAYSCAD_VIEW_CROSSHAIRS},
                 {"edges", RAYSCAD_VIEW_EDGES},
                 {"scales", RAYSCAD_VIEW_SCALES},
                 {"wireframe", CLI_VIEW_WIREFRAME}};
    const char *p = s;
    for (;;) {
        size_t n = strcspn(p, ",");
        size_t k = 0;
        while (k < sizeof parts / sizeof *parts &&
               (strlen(parts[k].name) != n || strncmp(parts[k].name, p, n) != 0))
            k++;
        if (k == sizeof parts / sizeof *parts) {
            snprintf(err, errlen,
                     "--view expects a comma list of axes, crosshairs, edges, scales and "
                     "wireframe, got '%s'",
                     s);
            return -1;
        }
        *flags |= parts[k].bit;
        if (!p[n]) return 0;
        p += n + 1;
    }
}

/* Add an output; -1 with a message when there are too many. */
static int add_output(cli_options *o, const char *path, char *err, size_t errlen)
{
    if (o->output_count == CLI_MAX_OUTPUTS) {
        snprintf(err, errlen, "more than %d outputs", CLI_MAX_OUTPUTS);
        return -1;
    }
    o->outputs[o->output_count++] = path;
    return 0;
}

int cli_parse_openscad_flag(int argc, char **argv, int *i, cli_options *o, char *err, size_t errlen)
{
    const char *a = argv[*i], *val = NULL;
    if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
        o->quiet = 1;
        return 1;
    }
    if (!strcmp(a, "--hardwarnings")) {
        o->hardwarnings = 1;
        return 1;
    }
    if (!strcmp(a, "--info")) {
        o->info = 1;
        return 1;
    }
    /* --render and --preview take an optional value after '=' only: openscad
     * would take the next argument (often the input file) as theirs. */
    if (cli_optional_value(a, "--render", &val)) {
        o->render = 1;
        o->throwntogether = 0;
        return 1;
    }
    if (cli_optional_value(a, "--preview", &val)) {
        if (val && *val && strcmp(val, "throwntogether") != 0 && strcmp(val, "opencsg") != 0) {
            snprintf(err, errlen, "--preview expects nothing or =throwntogether, got '%s'", val);
            return -1;
        }
        o->render = 0;
        o->throwntogether = val && !strcmp(val, "throwntogether");
        return 1;
    }
    if (cli_optional_value(a, "--debug", &val)) {
        o->debug = val ? val : "all";
        return 1;
    }
    static const char *const valued[] = {"--export-format",
                                         "--check-parameters",
                                         "--check-parameter-ranges",
                                         "--animate",
                                         "--view",
                                         "--csglimit",
                                         "-p",
                                         "-P",
                                         "-d",
                                         "-m",
                                         "-s",
                                         "-x"};
    const char *flag = NULL;
    for (size_t k = 0; !flag && k < sizeof valued / sizeof *valued; k++) {
        int r = cli_flag_value(argc, argv, i, valued[k], &val);
        if (r < 0) {
            snprintf(err, errlen, "%s needs a value", valued[k]);
            return -1;
        }
        if (r > 0) flag = valued[k];
    }
    if (!flag) return 0;
    if (!strcmp(flag, "--export-format")) {
        o->export_format = val;
    } else if (!strcmp(flag, "--check-parameters") || !strcmp(flag, "--check-parameter-ranges")) {
        int *b =
            !strcmp(flag, "--check-parameters") ? &o->check_parameters : &o->check_parameter_ranges;
        if (parse_bool(val, b) != 0) {
            snprintf(err, errlen, "%s expects true or false, got '%s'", flag, val);
            return -1;
        }
    } else if (!strcmp(flag, "--animate")) {
        if (cli_parse_int(val, 1, 1000000, &o->animate) != 0) {
            snprintf(err, errlen, "--animate expects a number of frames in 1..1000000, got '%s'",
                     val);
            return -1;
        }
    } else if (!strcmp(flag, "--view")) {
        return parse_view(val, &o->view_flags, err, errlen) == 0 ? 1 : -1;
    } else if (!strcmp(flag, "--csglimit")) {
        if (cli_parse_int(val, 0, 2147483647, &o->csglimit) != 0) {
            snprintf(err, errlen, "--csglimit expects a whole number, got '%s'", val);
            return -1;
        }
    } else if (!strcmp(flag, "-p")) {
        o->param_file = val;
    } else if (!strcmp(flag, "-P")) {
        o->param_set = val;
    } else if (!strcmp(flag, "-d")) {
        o->deps_file = val;
    } else if (!strcmp(flag, "-m")) {
        o->make_cmd = val;
    } else { /* -s, -x: openscad's old names of -o */
        o->deprecated_flags |= flag[1] == 's' ? 1 : 2;
        return add_output(o, val, err, errlen) == 0 ? 1 : -1;
    }
    return 1;
}

int cli_options_add_output(cli_options *o, const char *path, char *err, size_t errlen)
{
    return add_output(o, path, err, errlen);
}
