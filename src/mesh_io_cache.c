/* mesh_io_cache.c: mesh files kept from one frame of an animation to the
 * next. Reading a large file through assimp costs far more than a frame's
 * BVH build, and an animation reads the same files every frame; a file is
 * read again when its size, times or inode change. Entries no frame used
 * since the last sweep are dropped, so a scene that reads a new file per
 * frame does not pile them up. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "mesh_io.h"

struct entry {
	char *path;
	struct stat st;
	int used;
	scene_mesh m;
};

struct mesh_io_cache {
	struct entry *e;
	int n, cap;
	int hits;
};

mesh_io_cache *mesh_io_cache_new(void)
{
	return calloc(1, sizeof(mesh_io_cache));
}

void mesh_io_cache_free(mesh_io_cache *c)
{
	if (!c)
		return;
	for (int i = 0; i < c->n; i++) {
		free(c->e[i].path);
		scene_mesh_free(&c->e[i].m);
	}
	free(c->e);
	free(c);
}

int mesh_io_cache_hits(const mesh_io_cache *c)
{
	return c ? c->hits : 0;
}

static void *dup_array(const void *p, size_t n, size_t size, int *bad)
{
	if (!p)
		return NULL;
	void *q = malloc(n ? n * size : 1);
	if (!q)
		*bad = 1;
	else if (n)
		memcpy(q, p, n * size);
	return q;
}

/* A copy of what mesh_io_load fills (no textures: the scene adds those). */
static int copy_mesh(const scene_mesh *from, scene_mesh *to)
{
	int bad = 0;
	*to = *from;
	to->v = dup_array(from->v, from->n_v, sizeof *from->v, &bad);
	to->nrm = dup_array(from->nrm, from->n_nrm, sizeof *from->nrm, &bad);
	to->uv = dup_array(from->uv, from->n_uv, sizeof *from->uv, &bad);
	to->face = dup_array(from->face, from->n_faces, sizeof *from->face, &bad);
	to->face_nrm = dup_array(from->face_nrm, from->n_faces, sizeof *from->face_nrm, &bad);
	to->face_uv = dup_array(from->face_uv, from->n_faces, sizeof *from->face_uv, &bad);
	to->face_mat = dup_array(from->face_mat, from->n_faces, sizeof *from->face_mat, &bad);
	to->mats = NULL;
	to->n_mats = 0;
	if (bad) {
		scene_mesh_free(to);
		memset(to, 0, sizeof *to);
		return -1;
	}
	return 0;
}

static int same_file(const struct stat *a, const struct stat *b)
{
	return a->st_dev == b->st_dev && a->st_ino == b->st_ino && a->st_size == b->st_size &&
	       a->st_mtim.tv_sec == b->st_mtim.tv_sec && a->st_mtim.tv_nsec == b->st_mtim.tv_nsec &&
	       a->st_ctim.tv_sec == b->st_ctim.tv_sec && a->st_ctim.tv_nsec == b->st_ctim.tv_nsec;
}

static void keep(mesh_io_cache *c, const char *path, const struct stat *st, const scene_mesh *m)
{
	if (c->n == c->cap) {
		int cap = c->cap ? 2 * c->cap : 4;
		struct entry *e = realloc(c->e, cap * sizeof *e);
		if (!e)
			return;   /* a cache that cannot grow only costs time */
		c->e = e;
		c->cap = cap;
	}
	struct entry e = { .path = strdup(path), .st = *st, .used = 1 };
	if (!e.path || copy_mesh(m, &e.m)) {
		free(e.path);
		return;
	}
	c->e[c->n++] = e;
}

int mesh_io_load_cached(mesh_io_cache *c, const char *path, unsigned time_limit, double max_bytes, scene_mesh *m,
                        char *err, size_t errlen)
{
	struct stat st;
	if (!c || stat(path, &st) != 0)
		return mesh_io_load(path, time_limit, max_bytes, m, err, errlen);
	for (int i = 0; i < c->n; i++) {
		struct entry *e = &c->e[i];
		if (strcmp(e->path, path) != 0)
			continue;
		if (same_file(&e->st, &st) &&
		    mesh_io_fits(e->m.n_v, e->m.n_faces, e->m.nrm != NULL, max_bytes, err, errlen))
			return -1;
		if (same_file(&e->st, &st) && copy_mesh(&e->m, m) == 0) {
			e->used = 1;
			c->hits++;
			return 0;
		}
		free(e->path);   /* changed: read it again */
		scene_mesh_free(&e->m);
		c->e[i] = c->e[--c->n];
		break;
	}
	int rc = mesh_io_load(path, time_limit, max_bytes, m, err, errlen);
	if (rc == 0)
		keep(c, path, &st, m);
	return rc;
}

void mesh_io_cache_sweep(mesh_io_cache *c)
{
	if (!c)
		return;
	int k = 0;
	for (int i = 0; i < c->n; i++) {
		if (!c->e[i].used) {
			free(c->e[i].path);
			scene_mesh_free(&c->e[i].m);
			continue;
		}
		c->e[i].used = 0;
		c->e[k++] = c->e[i];
	}
	c->n = k;
}
