/*
 * settings.h — scene settings a .scad file states in top-level $rs_
 * variables (OpenSCAD ignores them), applied to the command's options where
 * no flag already set a value.
 */
#ifndef RAYSCAD_CLI_SETTINGS_H
#define RAYSCAD_CLI_SETTINGS_H

#include <stdio.h>

#include "options.h"

/* Apply the file's settings to o: each known $rs_ name sets its option when
 * the command line left that option at its default; a value out of range is
 * reported on `warn` (one line each) and ignored; unknown $rs_ names are
 * material variables or the user's own and are left alone.  The names:
 *   $rs_shadows (bool)       --shadows
 *   $rs_light_samples (1-16) --light-samples
 *   $rs_bounces (1-64)       --bounces
 *   $rs_refract (1-10)       --refract
 *   $rs_aperture (>= 0)      --aperture
 *   $rs_focus (>= 0)         --focus
 *   $rs_xray ((0,1])         --xray
 *   $rs_thickness (> 0 mm)   --absorb
 *   $rs_samples (1-16)       --samples
 *   $rs_path_trace (1-1e6)   --path-trace=N */
void cli_settings_apply(cli_options *o, const rayscad_model *m, FILE *warn);

#endif
