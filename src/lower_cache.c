/* lower_cache.c: the BVHs of meshes kept from one lowering to the next, so
 * that an animation builds a mesh's tree once while its triangles stay the
 * same (a mesh file read again, a mesh2 that does not follow the clock).
 *
 * A tree depends on its triangles, the builder and the layout only (the wide
 * layout's meshes stop at four triangles a leaf), so the key is the
 * mesh's triangles as lowering makes them, before the build, compared whole:
 * a hash alone could hand a mesh another's tree. Entries that one lowering
 * did not use are dropped at its end, so the cache holds one frame's meshes. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "lower.h"

struct entry {
	uint64_t hash;
	int builder, median_depth, layout, used;
	dev_prim *prims;   /* the triangles before the build, in their first order */
	int n;
	bvh_tree tree;
};

struct lower_cache {
	struct entry *e;
	int n, cap;
	int hits;
};

lower_cache *lower_cache_new(void)
{
	return calloc(1, sizeof(lower_cache));
}

static void entry_free(struct entry *e)
{
	free(e->prims);
	bvh_free(&e->tree);
}

void lower_cache_free(lower_cache *c)
{
	if (!c)
		return;
	for (int i = 0; i < c->n; i++)
		entry_free(&c->e[i]);
	free(c->e);
	free(c);
}

int lower_cache_hits(const lower_cache *c)
{
	return c ? c->hits : 0;
}

/* FNV-1a over the bytes, 8 at a time. */
static uint64_t hash_prims(const dev_prim *p, int n)
{
	const unsigned char *b = (const unsigned char *)p;
	size_t len = (size_t)n * sizeof *p;
	uint64_t h = 14695981039346656037ull, w;
	for (size_t i = 0; i + 8 <= len; i += 8) {
		memcpy(&w, b + i, 8);
		h = (h ^ w) * 1099511628211ull;
	}
	return h;
}

static int copy_tree(const bvh_tree *from, bvh_tree *to)
{
	*to = *from;
	to->nodes = malloc((from->n_nodes ? from->n_nodes : 1) * sizeof *to->nodes);
	to->prim_index = malloc((from->n_prims ? from->n_prims : 1) * sizeof *to->prim_index);
	if (!to->nodes || !to->prim_index) {
		free(to->nodes);
		free(to->prim_index);
		memset(to, 0, sizeof *to);
		return -1;
	}
	memcpy(to->nodes, from->nodes, from->n_nodes * sizeof *to->nodes);
	memcpy(to->prim_index, from->prim_index, from->n_prims * sizeof *to->prim_index);
	return 0;
}

static struct entry *find(lower_cache *c, const lower_options *o, const dev_prim *p, int n, uint64_t h)
{
	for (int i = 0; i < c->n; i++) {
		struct entry *e = &c->e[i];
		if (e->hash == h && e->n == n && e->builder == o->builder && e->layout == o->layout &&
		    (o->builder != LOWER_BVH_MEDIAN || e->median_depth == o->median_depth) &&
		    memcmp(e->prims, p, (size_t)n * sizeof *p) == 0)
			return e;
	}
	return NULL;
}

int lower_cache_find(lower_cache *c, const lower_options *o, const dev_prim *p, int n, bvh_tree *t)
{
	struct entry *e = find(c, o, p, n, hash_prims(p, n));
	if (!e || copy_tree(&e->tree, t))
		return 0;
	e->used = 1;
	c->hits++;
	return 1;
}

void lower_cache_keep(lower_cache *c, const lower_options *o, const dev_prim *p, int n, const bvh_tree *t)
{
	uint64_t h = hash_prims(p, n);
	if (find(c, o, p, n, h))
		return;   /* a second copy of a mesh within one scene */
	if (c->n == c->cap) {
		int cap = c->cap ? 2 * c->cap : 8;
		struct entry *e = realloc(c->e, cap * sizeof *e);
		if (!e)
			return;   /* a cache that cannot grow only costs time */
		c->e = e;
		c->cap = cap;
	}
	struct entry e = { .hash = h, .builder = o->builder, .median_depth = o->median_depth, .layout = o->layout,
	                  .used = 1, .n = n };
	e.prims = malloc((n ? n : 1) * sizeof *p);
	if (!e.prims || copy_tree(t, &e.tree)) {
		free(e.prims);
		return;
	}
	memcpy(e.prims, p, (size_t)n * sizeof *p);
	c->e[c->n++] = e;
}

void lower_cache_sweep(lower_cache *c)
{
	int k = 0;
	for (int i = 0; i < c->n; i++) {
		if (!c->e[i].used) {
			entry_free(&c->e[i]);
			continue;
		}
		c->e[i].used = 0;
		c->e[k++] = c->e[i];
	}
	c->n = k;
}
