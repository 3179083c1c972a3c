/*
 * registry.c — every builtin module and function of the library by name.
 *
 * The families list their entries (builtins.h); the first lookup puts them
 * all in two open-addressing tables keyed by the names' FNV-1a hash, the
 * hash names.c keeps on every interned name, so a lookup costs one probe
 * and one string comparison.  The tables are built once per process
 * (pthread_once) and only read afterwards, so evaluations on several
 * threads share them safely.
 */
#include <pthread.h>
#include <string.h>

#include "builtins.h"

enum { MODULE_SLOTS = 128, FUNCTION_SLOTS = 128 };

static const scad_module_def *const *const module_families[] = {
    scad_primitive_modules, scad_operation_modules, scad_extrude_modules, scad_hull_modules,
    scad_ops2d_modules,     scad_minkowski_modules, scad_import_modules,  scad_text_modules,
};

static const scad_function_def *const function_families[] = {scad_math_functions,
                                                             scad_dxf_functions};

static struct {
    const scad_module_def *module[MODULE_SLOTS];
    int module_id[MODULE_SLOTS];
    int nmodules;
    const scad_function_def *function[FUNCTION_SLOTS];
} reg;

static pthread_once_t built = PTHREAD_ONCE_INIT;

static void build(void)
{
    for (size_t f = 0; f < sizeof module_families / sizeof module_families[0]; f++)
        for (const scad_module_def *const *d = module_families[f]; *d; d++) {
            uint32_t k = scad_names_hash((*d)->name, strlen((*d)->name)) % MODULE_SLOTS;
            while (reg.module[k])
                k = (k + 1) % MODULE_SLOTS;
            reg.module[k] = *d;
            reg.module_id[k] = reg.nmodules++;
        }
    for (size_t f = 0; f < sizeof function_families / sizeof function_families[0]; f++)
        for (const scad_function_def *d = function_families[f]; d->name; d++) {
            uint32_t k = scad_names_hash(d->name, strlen(d->name)) % FUNCTION_SLOTS;
            while (reg.function[k])
                k = (k + 1) % FUNCTION_SLOTS;
            reg.function[k] = d;
        }
}

const scad_module_def *scad_registry_module(const char *name, int *id)
{
    pthread_once(&built, build);
    for (uint32_t k = scad_name_hash(name) % MODULE_SLOTS; reg.module[k];
         k = (k + 1) % MODULE_SLOTS) {
        if (strcmp(reg.module[k]->name, name) == 0) {
            if (id) *id = reg.module_id[k];
            return reg.module[k];
        }
    }
    return NULL;
}

const scad_function_def *scad_registry_function(const char *name)
{
    pthread_once(&built, build);
    for (uint32_t k = scad_name_hash(name) % FUNCTION_SLOTS; reg.function[k];
         k = (k + 1) % FUNCTION_SLOTS)
        if (strcmp(reg.function[k]->name, name) == 0) return reg.function[k];
    return NULL;
}

int scad_registry_module_count(void)
{
    pthread_once(&built, build);
    return reg.nmodules;
}
