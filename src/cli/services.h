/*
 * services.h — the outside services the language needs (scad_services),
 * implemented with src/io and src/mesh.
 */
#ifndef RAYSCAD_CLI_SERVICES_H
#define RAYSCAD_CLI_SERVICES_H

#include "../scad/scad.h"

/* The set rayscad's command uses: static, never freed. */
const scad_services *cli_services(void);

#endif
