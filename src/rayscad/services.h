/*
 * services.h — private to the library: the language's services as the
 * library provides them (services.c).
 */
#ifndef RAYSCAD_LIB_SERVICES_H
#define RAYSCAD_LIB_SERVICES_H

#include "../scad/scad.h"

/* The library's scad_services, each file, mesh and image reader the
 * caller's services (borrowed, may be NULL) set replacing the library's
 * own. */
void rayscad_scad_services(const rayscad_services *caller, scad_services *out);

/* The library's own whole-file read (rayscad_services.read_file). */
int rayscad_default_read_file(const char *path, size_t max, char **data, size_t *len, char *err,
                              size_t errlen);

#endif
