/*
 * services.h — for the suites that run src/scad directly: the library's own
 * services (files, meshes, images, polygon operations, text), as the
 * library's public calls give the language.
 */
#ifndef RAYSCAD_TESTS_SERVICES_H
#define RAYSCAD_TESTS_SERVICES_H

#include "../src/rayscad/services.h"

static inline const scad_services *test_services(void)
{
    static scad_services s;
    if (!s.read_file) rayscad_scad_services(NULL, &s);
    return &s;
}

#endif
