/* cli_ini.c: POV-Ray's INI files, line by line, into cli_pov's settings.
 *
 *   ; a comment                     Width=320
 *   [Low]                           +W160 +H120 -A
 *   Library_Path=/usr/share/povray-3.7/include
 *
 * As POV-Ray reads them (processoptions.cpp): "file.ini" reads the lines before
 * the first [Section]; "file.ini[Low]" only those of the sections named Low (in
 * any case). A line is KEY=VALUE, switches, a comment (';' or '#'), or a file
 * name (a scene, or another INI file). The text is registered with diag, so an
 * error names the INI file, line and column, with the line and a caret. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli_pov.h"

int cli_ini_named(const char *arg)
{
	size_t n = strcspn(arg, "[");
	return n >= 4 && strncasecmp(arg + n - 4, ".ini", 4) == 0;
}

static char *copy(const char *s, size_t n)
{
	return cli_pov_keep(strndup(s, n));
}

static src_loc at(int file, int line, const char *start, const char *p)
{
	return (src_loc){ file, line, (int)(p - start) + 1 };
}

/* "[Name]": the section's name, or an error at the '[' when the ']' is missing. */
static char *section(const char *p, const char *eol, src_loc loc)
{
	const char *close = memchr(p, ']', (size_t)(eol - p));
	if (!close) {
		diag_error(loc, "unterminated section header: ']' expected");
		diag_exit(1);
	}
	const char *b = p + 1, *e = close;
	while (b < e && isspace((unsigned char)*b))
		b++;
	while (e > b && isspace((unsigned char)e[-1]))
		e--;
	return copy(b, (size_t)(e - b));
}

/* The end of a line's meaningful text: before a ';' comment that follows a
 * space, and before trailing spaces. */
static const char *text_end(const char *p, const char *eol)
{
	for (const char *q = p; q < eol; q++)
		if (*q == ';' && (q == p || isspace((unsigned char)q[-1]))) {
			eol = q;
			break;
		}
	while (eol > p && isspace((unsigned char)eol[-1]))
		eol--;
	return eol;
}

/* "+W320 +H240 -D": each switch of the line. */
static void switches(cli_args *a, const char *p, const char *end, int file, int line, const char *start)
{
	while (p < end) {
		const char *e = p;
		while (e < end && !isspace((unsigned char)*e))
			e++;
		cli_pov_switch(a, copy(p, (size_t)(e - p)), at(file, line, start, p));
		for (p = e; p < end && isspace((unsigned char)*p); p++)
			;
	}
}

/* KEY=VALUE; a value in quotes loses them. */
static void key_value(cli_args *a, const char *p, const char *end, int file, int line, const char *start)
{
	const char *k = p;
	while (p < end && (isalnum((unsigned char)*p) || *p == '_'))
		p++;
	const char *key_end = p;
	while (p < end && (*p == ' ' || *p == '\t'))
		p++;
	if (p == end || *p != '=') {
		if (!memchr(k, '=', (size_t)(end - k)) && memchr(k, '.', (size_t)(end - k))) {   /* a file name */
			cli_pov_plain(a, copy(k, (size_t)(end - k)), at(file, line, start, k));
			return;
		}
		diag_error(at(file, line, start, p), "expected '=' after '%.*s'", (int)(key_end - k), k);
		diag_exit(1);
	}
	for (p++; p < end && (*p == ' ' || *p == '\t'); p++)
		;
	const char *v = p, *v_end = end;
	if (v_end - v >= 2 && (*v == '"' || *v == '\'') && v_end[-1] == *v) {
		v++;
		v_end--;
	}
	char *key = copy(k, (size_t)(key_end - k));
	cli_pov_setting(a, key, copy(v, (size_t)(v_end - v)), at(file, line, start, k), at(file, line, start, v));
}

static int read_source(const char *path, src_loc loc)
{
	size_t len;
	char *text = diag_read_file(path, &len);
	if (!text) {
		diag_error(loc, "cannot read the INI file '%s': %s", path, strerror(errno));
		diag_exit(1);
	}
	return diag_add_source(path, text, len);
}

#define MAX_NESTING 16

void cli_ini_read(cli_args *a, const char *spec, src_loc loc)
{
	static int nesting;   /* an INI file that names itself would never end */
	if (nesting == MAX_NESTING) {
		diag_error(loc, "INI files name each other more than %d deep", MAX_NESTING);
		diag_exit(1);
	}
	nesting++;
	char *path = copy(spec, strcspn(spec, "[")), *want = NULL;
	if (spec[strlen(path)]) {
		const char *open = spec + strlen(path), *close = strchr(open, ']');
		if (!close || close[1]) {
			diag_error(loc, "'%s': a section is named as FILE.ini[SECTION]", spec);
			diag_exit(1);
		}
		want = copy(open + 1, (size_t)(close - open - 1));
	}
	int file = read_source(path, loc);
	size_t len;
	const char *text = diag_source_text(file, &len), *end = text + len;
	int active = 1, line = 1;
	for (const char *start = text; start < end; line++) {
		const char *eol = memchr(start, '\n', (size_t)(end - start));
		eol = eol ? eol : end;
		const char *p = start;
		if (p == text && eol - p >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0)   /* a UTF-8 mark, as Windows editors write */
			p += 3;
		while (p < eol && isspace((unsigned char)*p))
			p++;
		if (p < eol && *p == '[') {
			char *name = section(p, eol, at(file, line, start, p));
			active = want && strcasecmp(name, want) == 0;
		} else if (active && p < eol && *p != ';' && *p != '#') {
			const char *e = text_end(p, eol);
			if (*p == '+' || *p == '-')
				switches(a, p, e, file, line, start);
			else
				key_value(a, p, e, file, line, start);
		}
		start = eol < end ? eol + 1 : end;
	}
	nesting--;
}
