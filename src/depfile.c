/* depfile.c: the make rule of --depfile. Names are written as make reads
 * them: a space, '#' or ':' after a backslash, '$' doubled. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "depfile.h"

struct list {
	char **v;
	int n, cap;
};

struct depfile {
	struct list kind[2];   /* DEPFILE_TARGET, DEPFILE_INPUT */
	int failed;            /* memory ran out while adding */
};

depfile *depfile_new(void)
{
	return calloc(1, sizeof(depfile));
}

int depfile_add(depfile *d, int kind, const char *path)
{
	struct list *l = &d->kind[kind];
	for (int i = 0; i < l->n; i++)
		if (strcmp(l->v[i], path) == 0)
			return 0;
	if (l->n == l->cap) {
		int cap = l->cap ? 2 * l->cap : 16;
		char **v = realloc(l->v, cap * sizeof *v);
		if (!v)
			return d->failed = -1;
		l->v = v;
		l->cap = cap;
	}
	if (!(l->v[l->n] = strdup(path)))
		return d->failed = -1;
	l->n++;
	return 0;
}

void depfile_on_read(void *ctx, const char *path)
{
	depfile_add(ctx, DEPFILE_INPUT, path);
}

static void put_name(FILE *f, const char *s)
{
	for (; *s; s++) {
		if (*s == '$')
			fputc('$', f);
		else if (*s == ' ' || *s == '#' || *s == ':' || *s == '\\' || *s == '\t')
			fputc('\\', f);
		fputc(*s, f);
	}
}

static void put_rule(FILE *f, const depfile *d)
{
	const struct list *t = &d->kind[DEPFILE_TARGET], *in = &d->kind[DEPFILE_INPUT];
	for (int i = 0; i < t->n; i++) {
		put_name(f, t->v[i]);
		fputs(i + 1 < t->n ? " \\\n" : ":", f);
	}
	for (int i = 0; i < in->n; i++) {
		fputs(" \\\n  ", f);
		put_name(f, in->v[i]);
	}
	fputc('\n', f);
	for (int i = 0; i < in->n; i++) {   /* gcc -MP: a deleted include is no error */
		fputc('\n', f);
		put_name(f, in->v[i]);
		fputs(":\n", f);
	}
}

int depfile_write(const depfile *d, const char *path)
{
	if (d->failed) {
		fprintf(stderr, "eclat: --depfile: out of memory\n");
		return -1;
	}
	char *tmp = malloc(strlen(path) + 32);
	if (!tmp) {
		fprintf(stderr, "eclat: --depfile: out of memory\n");
		return -1;
	}
	sprintf(tmp, "%s.eclat-%ld.tmp", path, (long)getpid());
	FILE *f = fopen(tmp, "w");
	int rc = f ? 0 : -1;
	if (f) {
		put_rule(f, d);
		rc = ferror(f) | fclose(f) ? -1 : 0;
	}
	if (rc == 0 && rename(tmp, path) != 0)
		rc = -1;
	if (rc) {
		fprintf(stderr, "eclat: cannot write the depfile '%s': %s\n", path, strerror(errno));
		remove(tmp);
	}
	free(tmp);
	return rc;
}

void depfile_free(depfile *d)
{
	if (!d)
		return;
	for (int k = 0; k < 2; k++) {
		for (int i = 0; i < d->kind[k].n; i++)
			free(d->kind[k].v[i]);
		free(d->kind[k].v);
	}
	free(d);
}
