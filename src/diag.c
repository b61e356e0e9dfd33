/* diag.c: the source table and error messages with the source line and a caret. */
#include "diag.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

struct source {
	char *name;
	char *text;
	size_t len;
};

static struct source *sources;
static int n_sources;
static int n_errors;

void (*diag_before_exit)(void);

void diag_exit(int status)
{
	if (diag_before_exit)
		diag_before_exit();
	exit(status);
}

int diag_add_source(const char *name, char *text, size_t len)
{
	struct source *s = realloc(sources, (n_sources + 1) * sizeof *s);
	if (!s) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	sources = s;
	sources[n_sources] = (struct source){ strdup(name), text, len };
	return n_sources++;
}

const char *diag_source_name(int file)
{
	return file >= 0 && file < n_sources ? sources[file].name : "eclat";
}

const char *diag_source_text(int file, size_t *len)
{
	if (file < 0 || file >= n_sources)
		return NULL;
	*len = sources[file].len;
	return sources[file].text;
}

/* Prints the source line of loc and a caret under its column. Tabs in the line
 * are copied into the caret's indentation so the caret lines up in any editor. */
static void show_line(src_loc loc)
{
	size_t len;
	const char *text = diag_source_text(loc.file, &len);
	if (!text || loc.line < 1)
		return;
	const char *p = text, *end = text + len;
	for (int l = 1; l < loc.line && p < end; l++) {
		const char *nl = memchr(p, '\n', end - p);
		p = nl ? nl + 1 : end;
	}
	const char *eol = memchr(p, '\n', end - p);
	if (!eol)
		eol = end;
	fputc(' ', stderr);
	for (const char *q = p; q < eol; q++)
		fputc(*q == '\0' || *q == '\r' ? ' ' : *q, stderr);
	fputs("\n ", stderr);
	for (int c = 1; c < loc.col && p + c - 1 < eol; c++)
		fputc(p[c - 1] == '\t' ? '\t' : ' ', stderr);
	fputs("^\n", stderr);
}

static void report(src_loc loc, const char *kind, const char *fmt, va_list ap)
{
	if (loc.file >= 0)
		fprintf(stderr, "%s:%d:%d: %s: ", diag_source_name(loc.file), loc.line, loc.col, kind);
	else
		fprintf(stderr, "eclat: %s: ", kind);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	show_line(loc);
}

void diag_error(src_loc loc, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	report(loc, "error", fmt, ap);
	va_end(ap);
	n_errors++;
}

void diag_warning(src_loc loc, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	report(loc, "warning", fmt, ap);
	va_end(ap);
}

void diag_note(src_loc loc, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	report(loc, "note", fmt, ap);
	va_end(ap);
}

int diag_error_count(void)
{
	return n_errors;
}

char *diag_read_file(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	struct stat st = { 0 };
	int regular = fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode);
	if (!regular && S_ISDIR(st.st_mode)) {
		fclose(f);
		errno = EISDIR;
		return NULL;
	}
	/* a device or a pipe may never end: it gets less room than a real file */
	size_t max = regular ? DIAG_MAX_FILE : DIAG_MAX_FILE / 16;
	size_t cap = 1 << 16, n = 0;
	char *buf = malloc(cap + 1);
	size_t got;
	while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
		n += got;
		if (n >= max) {   /* /dev/zero, or a file no scene is */
			free(buf);
			fclose(f);
			errno = EFBIG;
			return NULL;
		}
		if (n == cap) {
			char *b = realloc(buf, 2 * cap + 1);
			if (!b) {
				free(buf);
				buf = NULL;
			}
			buf = b;
			cap *= 2;
		}
	}
	int err = ferror(f) ? errno : 0;
	fclose(f);
	if (!buf || err) {
		free(buf);
		errno = err ? err : ENOMEM;
		return NULL;
	}
	buf[n] = '\0';
	*len = n;
	return buf;
}

void diag_free_all(void)
{
	for (int i = 0; i < n_sources; i++) {
		free(sources[i].name);
		free(sources[i].text);
	}
	free(sources);
	sources = NULL;
	n_sources = 0;
	n_errors = 0;   /* a fresh start, for a program (a fuzzer) that reads many scenes */
}
