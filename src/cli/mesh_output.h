/*
 * mesh_output.h — the command's mesh outputs (.stl .off .obj .ply) and
 * --measure: root 0 of a scene (the model, its top-level objects unioned)
 * sampled by the library's tri-dexel rays, contoured, optionally
 * simplified to --mesh-tolerance, and written through OpenMesh.
 */
#ifndef RAYSCAD_CLI_MESH_OUTPUT_H
#define RAYSCAD_CLI_MESH_OUTPUT_H

#include "options.h"
#include "outputs.h"

/* Sample root 0 of scene (borrowed) once on the grid o->mesh_size (or the
 * default), then, as o asks: write the mesh (simplified once
 * to --mesh-tolerance) to each of the n outputs outs[i] under the name paths[i],
 * and print the measurement on stdout when o->measure (as JSON with
 * o->json).  Warnings (thin walls the grid cannot
 * resolve) go to stderr.  Returns the exit status: 0, or 1 when the model
 * cannot be meshed or the file cannot be written (a message on stderr; the
 * output is then left untouched). */
int cli_mesh_output(const cli_options *o, const rayscad_scene *scene, cli_output *outs,
                    const char *const *paths, int n);

#endif
