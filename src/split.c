/* split.c: the scene's identity (its files' contents and the options that
 * change pixels) that splits, merges and resumes check. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "split.h"

void split_note_input(const char *path, void *ctx)
{
	split_inputs *in = ctx;
	char *r = realpath(path, NULL);
	if (!r)   /* the open that follows fails and says why */
		return;
	for (int i = 0; i < in->n; i++)
		if (strcmp(in->paths[i], r) == 0) {
			free(r);
			return;
		}
	if (in->n == in->cap) {
		int cap = in->cap ? 2 * in->cap : 16;
		char **p = realloc(in->paths, cap * sizeof *p);
		if (!p) {
			free(r);
			return;
		}
		in->paths = p;
		in->cap = cap;
	}
	in->paths[in->n++] = r;
}

void split_inputs_free(split_inputs *in)
{
	for (int i = 0; i < in->n; i++)
		free(in->paths[i]);
	free(in->paths);
	*in = (split_inputs){ 0 };
}

/* FNV-1a over the file's bytes: a change of any byte changes it, which is all
 * a check against edits between parts needs (it is no defence against forgery). */
static int hash_file(const char *path, uint64_t *h)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return -1;
	unsigned char buf[65536];
	size_t n;
	*h = 0xcbf29ce484222325ull;
	while ((n = fread(buf, 1, sizeof buf, f)) > 0)
		for (size_t i = 0; i < n; i++)
			*h = (*h ^ buf[i]) * 0x100000001b3ull;
	int bad = ferror(f);
	fclose(f);
	return bad ? -1 : 0;
}

static int append(char **s, size_t *len, const char *path, uint64_t h)
{
	size_t add = strlen(path) + 18;
	char *p = realloc(*s, *len + add + 1);
	if (!p)
		return -1;
	*s = p;
	*len += (size_t)sprintf(p + *len, "%016llx %s\n", (unsigned long long)h, path);
	return 0;
}

static int add_file(char **s, size_t *len, const char *path)
{
	uint64_t h;
	if (hash_file(path, &h)) {
		fprintf(stderr, "eclat: cannot read '%s' to record the scene's content: %s\n", path, strerror(errno));
		return -1;
	}
	return append(s, len, path, h);
}

int split_key_make(split_key *k, const char *scene, const split_inputs *in, const char *options)
{
	size_t len = 0;
	char *files = NULL, *abs = realpath(scene, NULL);
	int rc = add_file(&files, &len, abs ? abs : scene);
	for (int i = 0; rc == 0 && i < in->n; i++)
		if (!abs || strcmp(in->paths[i], abs) != 0)
			rc = add_file(&files, &len, in->paths[i]);
	free(abs);
	k->files = files;
	k->options = strdup(options);
	if (rc == 0 && k->files && k->options)
		return 0;
	split_key_free(k);
	return -1;
}

void split_key_free(split_key *k)
{
	free(k->options);
	free(k->files);
	k->options = k->files = NULL;
}

/* The line of list whose text up to sep is key's, or NULL. */
static const char *find_line(const char *list, const char *key, size_t klen, char sep, int key_first)
{
	for (const char *l = list; l && *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : NULL) {
		const char *end = strchr(l, '\n'), *e = end ? end : l + strlen(l);
		const char *k = key_first ? l : memchr(l, sep, (size_t)(e - l));
		if (!k)
			continue;
		if (!key_first)
			k++;
		const char *kend = key_first ? memchr(l, sep, (size_t)(e - l)) : e;
		if (kend && (size_t)(kend - k) == klen && memcmp(k, key, klen) == 0)
			return l;
	}
	return NULL;
}

static size_t line_len(const char *l)
{
	const char *e = strchr(l, '\n');
	return e ? (size_t)(e - l) : strlen(l);
}

/* The first option whose value differs, or that one list lacks. */
static int options_diff(const char *was, const char *now, char *why, size_t n)
{
	for (int pass = 0; pass < 2; pass++) {
		const char *a = pass ? now : was, *b = pass ? was : now;
		for (const char *l = a; *l; l += line_len(l) + (l[line_len(l)] == '\n')) {
			size_t len = line_len(l);
			const char *eq = memchr(l, '=', len);
			size_t klen = eq ? (size_t)(eq - l) : len;
			const char *m = find_line(b, l, klen, '=', 1);
			if (m && line_len(m) == len && memcmp(m, l, len) == 0)
				continue;
			const char *wl = pass ? m : l, *nl = pass ? l : m;
			snprintf(why, n, "%.*s was %.*s, is %.*s", (int)klen, l,
			         wl ? (int)(line_len(wl) - klen - 1) : 4, wl ? wl + klen + 1 : "none",
			         nl ? (int)(line_len(nl) - klen - 1) : 4, nl ? nl + klen + 1 : "none");
			return 1;
		}
	}
	return 0;
}

/* Another scene file (the first line), or the first file changed, no longer
 * read, or read only now. */
static int files_diff(const char *was, const char *now, char *why, size_t n)
{
	size_t wl = line_len(was), nl = line_len(now);
	if (wl > 17 && nl > 17 && (wl != nl || memcmp(was + 17, now + 17, wl - 17) != 0)) {
		snprintf(why, n, "the scene was '%.*s', is '%.*s'", (int)(wl - 17), was + 17, (int)(nl - 17), now + 17);
		return 1;
	}
	for (int pass = 0; pass < 2; pass++) {
		const char *a = pass ? now : was, *b = pass ? was : now;
		for (const char *l = a; *l; l += line_len(l) + (l[line_len(l)] == '\n')) {
			size_t len = line_len(l);
			if (len < 18)
				continue;
			const char *path = l + 17;
			size_t plen = len - 17;
			const char *m = find_line(b, path, plen, ' ', 0);
			if (m && memcmp(m, l, 16) == 0)
				continue;
			snprintf(why, n, "'%.*s' %s", (int)plen, path,
			         m ? "changed" : pass ? "is read now, but was not" : "was read, but is not now");
			return 1;
		}
	}
	return 0;
}

int split_key_diff(const split_key *was, const split_key *now, char *why, size_t n)
{
	return options_diff(was->options, now->options, why, n) || files_diff(was->files, now->files, why, n);
}

void split_info_free(split_info *info)
{
	split_key_free(&info->key);
	free(info->scene);
	info->scene = NULL;
}

int split_in_region(const split_info *info, int x, int y)
{
	return x >= info->region[0] && x <= info->region[2] && y >= info->region[1] && y <= info->region[3];
}
