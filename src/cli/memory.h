/*
 * memory.h — the command's memory policy (--max-memory): the process's
 * data limit, lifted around the foreign work it must not see, and the note
 * that names it on an "out of memory" error (memory.c says why the data
 * limit).
 */
#ifndef RAYSCAD_CLI_MEMORY_H
#define RAYSCAD_CLI_MEMORY_H

#include <sys/resource.h>

#include "options.h"

/* The default of --max-memory: 3/4 of the machine's memory (or of the
 * cgroup's memory.max, when that is lower), plus what the process reserves
 * for stacks whatever the model — the evaluator's 1 GiB thread stack and
 * two stacks per core or --threads worker (ours and OpenImageIO's pool) —
 * since the limit counts those reservations too (memory.c says why). */
unsigned long long cli_default_max_memory(const cli_options *o);

/* bytes as --max-memory reads it back: "300M", "2G", "1536K"; one decimal
 * when not a whole number of K, M or G ("17.6G"). */
void cli_format_size(unsigned long long bytes, char *buf, size_t len);

/* Print "rayscad: error: MSG" on stderr.  Every library words a failed
 * allocation as "out of memory"; while main's data limit is in force such
 * a message ends with which limit it was: "… (more than --max-memory 2G)". */
void cli_print_error(const cli_options *o, const char *msg);

/* The same note for a message printed some other way (the evaluator's
 * file:line:col lines): " (more than --max-memory 2G)" in buf, or "". */
const char *cli_memory_note(const cli_options *o, const char *msg, char *buf, size_t len);

/* Load the image adapter (OpenImageIO, rayscad_image_load) unless it is
 * loaded already, with the process's data limit lifted for the while: the
 * static initialisers of its 260 libraries do not survive a failed
 * allocation (measured: std::bad_alloc and std::system_error thrown out of
 * them, and null dereferences, with limits from 50 to 95 MiB), so the load
 * must not meet --max-memory, whatever the model holds at that moment.
 * Call it before the adapter would be loaded under the limit. */
void cli_load_image_adapter(void);

/* Lift the soft data limit (--max-memory) to the hard one around work the
 * limit must not see: returns 1 when it was lifted, keeping the old limit
 * in *was for cli_data_limit_restore, which puts it back. */
int cli_data_limit_lift(struct rlimit *was);
void cli_data_limit_restore(int lifted, const struct rlimit *was);

/* Cap the process's data memory at o->max_memory (its default when the
 * flag was not given), or keep a lower limit the caller already set;
 * records which in o->max_memory_enforced. */
void cli_apply_memory_limit(cli_options *o);

/* surface()'s PNG reads (rayscad_services.read_image) under the limit:
 * OpenImageIO reads with the limit lifted, when the image's pixels fit
 * beside what the process holds. */
int cli_read_image(void *ud, const char *path, int *width, int *height, int *channels,
                   float **pixels, char *err, size_t errlen);

#endif
