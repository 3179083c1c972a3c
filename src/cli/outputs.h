/*
 * outputs.h — what each -o writes: its format (from --export-format or the
 * file's extension, as openscad 2021.01 picks it), and where the writers
 * put it: a file given with another extension, or "-" (the standard
 * output), is written under a temporary name with the format's extension
 * and then moved into place or copied out.
 */
#ifndef RAYSCAD_CLI_OUTPUTS_H
#define RAYSCAD_CLI_OUTPUTS_H

#include <stddef.h>

typedef enum output_kind {
    OUTPUT_IMAGE, /* PNG, JPEG, TIFF, EXR … through OpenImageIO */
    OUTPUT_POV,   /* the scene and camera for POV-Ray */
    OUTPUT_MESH,  /* STL, OFF, OBJ, PLY, AMF, 3MF */
    OUTPUT_2D,    /* SVG, DXF, PDF of a 2D model */
    OUTPUT_ECHO,  /* the ECHO and WARNING lines */
    OUTPUT_CSG,   /* the evaluated tree */
    OUTPUT_AST,   /* the parsed file printed back */
    OUTPUT_TERM,  /* openscad's CSG term text */
} output_kind;

typedef struct cli_output {
    const char *path; /* as given; "-": the standard output */
    output_kind kind;
    char ext[16];     /* the format's file extension, without the dot */
    int ascii;        /* meshes: text (STL unless binstl, and --ascii) */
    char write[4096]; /* where the writer writes */
    int temporary;    /* write is a temporary name (cli_output_finish) */
} cli_output;

/* Resolve path's format: fmt (--export-format, may be NULL) or the
 * extension.  Returns 0; 1 when the format is unknown or not written by
 * rayscad (message in err; openscad's own words for a missing suffix);
 * `ascii` is --ascii. */
int cli_output_resolve(const char *path, const char *fmt, int ascii, cli_output *out, char *err,
                       size_t errlen);

/* The path of frame `frame` of an animation, as openscad names it:
 * "f.png" → "f00003.png" (into buf); "-" stays "-". */
const char *cli_output_frame_path(const char *path, int frame, char *buf, size_t len);

/* Choose out->write for a path (which may be a frame's name): the path
 * itself when its extension is the format's, else a temporary name. 0 or
 * -1 (message in err). */
int cli_output_begin(cli_output *out, const char *path, char *err, size_t errlen);

/* After the writer: move a temporary file to path, or copy it to the
 * standard output for "-", and remove it; ok 0 only removes it.  0 or -1
 * (message in err). */
int cli_output_finish(cli_output *out, const char *path, int ok, char *err, size_t errlen);

/* begin, write(ctx, out->write, …), finish: the whole of writing output
 * out under the name path.  0, or -1 with a message in err. */
typedef int (*cli_writer)(void *ctx, const char *write_path, char *err, size_t errlen);
int cli_output_write(cli_output *out, const char *path, cli_writer write, void *ctx, char *err,
                     size_t errlen);

#endif
