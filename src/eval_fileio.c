/* eval_fileio.c: POV-Ray's file directives, #fopen, #read, #write and #fclose.
 *
 *   #fopen Handle "Name" read|write|append
 *   #write (Handle, Item...)       strings as they are, floats as %g, vectors <%g,%g,...>
 *   #read (Handle, Identifier...)  one value each: "string", float or <vector>
 *   #fclose Handle
 *
 * What POV-Ray 3.7 does, found by experiment (povray 3.7.0.10): a file is read
 * from the folders an #include searches and written where the name says (relative
 * to the current folder); the handle is an identifier, so defined(Handle) and
 * #ifdef work; at the end of the file #read closes it and undefines the handle
 * (scenes loop with #while (defined(F))) as soon as the value it read is the
 * last, leaving the identifiers it did not reach as they were; #fclose of a
 * handle that is not open does nothing; #write puts a space after a vector and nothing between
 * items, and refuses colours. Files left open are closed at the end of the
 * scene. Which files a scene may open is eval_access.c's to say. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

struct eval_file {
	char *handle;
	char *path;
	FILE *f;
	bool reading;
};

static struct eval_file *find_open(struct eval *e, const char *handle)
{
	for (int i = 0; i < e->n_files; i++)
		if (strcmp(e->files[i].handle, handle) == 0)
			return &e->files[i];
	return NULL;
}

static void close_file(struct eval *e, struct eval_file *f)
{
	fclose(f->f);
	eval_undef(e, f->handle);
	free(f->handle);
	free(f->path);
	*f = e->files[--e->n_files];
}

void eval_files_close(struct eval *e)
{
	while (e->n_files > 0)
		close_file(e, &e->files[e->n_files - 1]);
	free(e->files);
	e->files = NULL;
}

/* #fopen Handle "Name" Mode */
static void run_fopen(struct eval *e, const ast_node *d)
{
	const char *handle = d->kids[0]->str, *mode = d->kids[2]->str;
	bool reading = strcmp(mode, "read") == 0;
	if (!reading && strcmp(mode, "write") != 0 && strcmp(mode, "append") != 0) {
		eval_error(e, d->kids[2]->loc, "expected read, write or append, found '%s'", mode);
		return;
	}
	char *name, *path;
	if (eval_expect_string(e, d->kids[1], &name))
		return;
	path = reading ? eval_find_file(e, d->loc.file, name) : NULL;
	if (eval_access(e, path ? path : name, !reading, d->loc, "#fopen")) {
		free(name);
		free(path);
		return;
	}
	FILE *f = fopen(path ? path : name, reading ? "r" : mode[0] == 'w' ? "w" : "a");
	if (!f) {
		eval_error(e, d->kids[1]->loc, "cannot open '%s' for %s: %s", name,
		           reading ? "reading" : "writing", strerror(errno));
		free(name);
		free(path);
		return;
	}
	struct eval_file *old = find_open(e, handle);
	if (old)
		close_file(e, old);   /* POV-Ray too lets a handle be opened again */
	e->files = eval_xrealloc(e->files, (e->n_files + 1) * sizeof *e->files);
	e->files[e->n_files++] = (struct eval_file){ eval_xstrdup(handle), path ? path : eval_xstrdup(name), f, reading };
	free(name);
	eval_assign(e, handle, (value){ .kind = V_OTHER, .str = eval_xstrdup("file") }, false);
}

/* The open file the first item of #read or #write names. */
static struct eval_file *handle_of(struct eval *e, const ast_node *d, bool reading)
{
	if (d->n_kids == 0 || d->kids[0]->kind != AST_IDENT) {
		eval_error(e, d->n_kids ? d->kids[0]->loc : d->loc, "#%s needs a file handle first", d->str);
		return NULL;
	}
	struct eval_file *f = find_open(e, d->kids[0]->str);
	if (!f)
		eval_error(e, d->kids[0]->loc, "'%s' is not an open file (see #fopen)", d->kids[0]->str);
	else if (f->reading != reading)
		eval_error(e, d->kids[0]->loc, "'%s' is open for %s", f->handle, f->reading ? "reading" : "writing");
	return f && f->reading == reading ? f : NULL;
}

/* #write (Handle, Item...) */
static void run_write(struct eval *e, const ast_node *d)
{
	struct eval_file *f = handle_of(e, d, false);
	for (int i = 1; f && i < d->n_kids; i++) {
		value v;
		if (eval_expr(e, d->kids[i], &v))
			return;
		if (v.kind == V_STRING) {
			fputs(v.str, f->f);
		} else if (v.kind == V_FLOAT) {
			fprintf(f->f, "%g", v.v[0]);
		} else if (v.kind == V_VECTOR) {
			fputc('<', f->f);
			for (int k = 0; k < v.n; k++)
				fprintf(f->f, k ? ",%g" : "%g", v.v[k]);
			fputs("> ", f->f);
		} else {
			eval_error(e, d->kids[i]->loc, "#write takes strings, floats and vectors, not %s",
			           eval_kind_name(v.kind));
			eval_value_free(&v);
			return;
		}
		eval_value_free(&v);
	}
}

/* ---- #read: the values of a file, separated by commas or white space ---- */

static int skip_separators(FILE *f)
{
	int ch;
	while ((ch = fgetc(f)) != EOF && (isspace(ch) || ch == ','))
		;
	return ch;
}

/* A number, its first character ch already read. */
static int read_number(FILE *f, int ch, double *out)
{
	char buf[64];
	size_t n = 0;
	while (ch != EOF && (isdigit(ch) || strchr("+-.eE", ch)) && n < sizeof buf - 1) {
		buf[n++] = (char)ch;
		ch = fgetc(f);
	}
	if (ch != EOF)
		ungetc(ch, f);
	buf[n] = '\0';
	char *end;
	*out = strtod(buf, &end);
	return n > 0 && *end == '\0' ? 0 : -1;
}

/* "text" with POV-Ray's escapes, the quote already read. */
static int read_string(FILE *f, value *out)
{
	size_t n = 0, cap = 64;
	char *s = eval_xrealloc(NULL, cap);
	int ch;
	while ((ch = fgetc(f)) != EOF && ch != '"') {
		if (ch == '\\' && (ch = fgetc(f)) != EOF)
			ch = ch == 'n' ? '\n' : ch == 't' ? '\t' : ch;
		if (n + 2 > cap)
			s = eval_xrealloc(s, cap *= 2);
		s[n++] = (char)ch;
	}
	s[n] = '\0';
	*out = (value){ .kind = V_STRING, .str = s };
	return ch == '"' ? 0 : -1;
}

/* <A, B, ...>, the '<' already read. */
static int read_vector(FILE *f, value *out)
{
	*out = (value){ .kind = V_VECTOR };
	int ch;
	while ((ch = skip_separators(f)) != EOF && ch != '>') {
		if (out->n == 5 || read_number(f, ch, &out->v[out->n]))
			return -1;
		out->n++;
	}
	return ch == '>' && out->n >= 2 ? 0 : -1;
}

/* The next value of f: 1 at its end, -1 when it holds something else. */
static int read_value(FILE *f, value *out)
{
	int ch = skip_separators(f);
	if (ch == EOF)
		return 1;
	if (ch == '"')
		return read_string(f, out);
	if (ch == '<')
		return read_vector(f, out);
	*out = (value){ .kind = V_FLOAT, .n = 1 };
	return read_number(f, ch, &out->v[0]);
}

/* #read (Handle, Identifier...) */
static void run_read(struct eval *e, const ast_node *d)
{
	struct eval_file *f = handle_of(e, d, true);
	for (int i = 1; f && i < d->n_kids; i++) {
		const ast_node *target = d->kids[i];
		if (target->kind != AST_IDENT) {
			eval_error(e, target->loc, "#read reads into identifiers, not %s",
			           target->kind == AST_INDEX ? "array elements" : "expressions");
			return;
		}
		value v = { 0 };
		int rc = read_value(f->f, &v);
		if (rc == 1) {
			close_file(e, f);
			return;
		}
		if (rc < 0) {
			eval_value_free(&v);
			eval_error(e, target->loc, "#read: '%s' holds something that is not a string, a float or a vector",
			           f->path);
			return;
		}
		eval_assign(e, target->str, v, false);
		int ch = skip_separators(f->f);
		if (ch == EOF) {
			close_file(e, f);
			return;
		}
		ungetc(ch, f->f);
	}
}

void eval_file_io(struct eval *e, const ast_node *d)
{
	if (strcmp(d->str, "fopen") == 0) {
		run_fopen(e, d);
	} else if (strcmp(d->str, "fclose") == 0) {
		struct eval_file *f = find_open(e, d->kids[0]->str);
		if (f)
			close_file(e, f);
	} else if (strcmp(d->str, "read") == 0) {
		run_read(e, d);
	} else {
		run_write(e, d);
	}
}
