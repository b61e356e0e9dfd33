/* diag.h: source files and the messages that point into them.
 *
 * Every stage reports problems against a src_loc, so an error found late (a
 * degenerate triangle while lowering) still names the .scn line that caused it:
 *
 *   FILE:LINE:COL: error: MESSAGE
 *    LINE TEXT
 *        ^
 */
#ifndef ECLAT_DIAG_H
#define ECLAT_DIAG_H

#include <stddef.h>

typedef struct {
	int file;       /* index into the source table; -1 when there is no source */
	int line, col;  /* 1-based; col counts bytes */
} src_loc;

#define SRC_NOWHERE ((src_loc){ -1, 0, 0 })

/* Registers a source text (owned by diag from now on) and returns its file index. */
int diag_add_source(const char *name, char *text, size_t len);
const char *diag_source_name(int file);
const char *diag_source_text(int file, size_t *len);

void diag_error(src_loc loc, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
void diag_warning(src_loc loc, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* A follow-up line ("note: ...") for the message just printed. */
void diag_note(src_loc loc, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
int diag_error_count(void);

/* Ends eclat with status, through exit() once diag_before_exit, when set, has
 * run: every exit() of eclat's own code is a diag_exit. src/image_module.c sets
 * it, because an exit() while its module loads on another thread would run the
 * half-loaded libraries' destructors beside their constructors. */
extern void (*diag_before_exit)(void);
_Noreturn void diag_exit(int status);

/* Reads a whole file into a NUL-terminated buffer; NULL with errno set on failure
 * (EISDIR for a folder, EFBIG past DIAG_MAX_FILE bytes, or a 16th of that from a
 * device or a pipe, such as /dev/zero). */
#define DIAG_MAX_FILE ((size_t)1 << 30)
char *diag_read_file(const char *path, size_t *len);
void diag_free_all(void);

#endif
