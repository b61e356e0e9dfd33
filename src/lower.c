/* lower.c: bakes transforms into world-space primitives, maps POV-Ray textures to
 * physically based materials, builds the BVH and reorders the primitives into its
 * leaf order (so a leaf is a contiguous range), and lists the emitters. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "lower.h"
#include "shape.h"
#include "csg.h"

/* The device reads these structs byte for byte: the layouts must not drift. */
_Static_assert(sizeof(float4) == 16, "float4 is 16 bytes");
_Static_assert(sizeof(bvh_node) == 32, "bvh_node is 32 bytes");
_Static_assert(offsetof(bvh_node, max_x) == 16, "bvh_node max at 16");
_Static_assert(sizeof(bvh_wnode) == 64, "bvh_wnode is 64 bytes");
_Static_assert(offsetof(bvh_wnode, qlo_x) == 16 && offsetof(bvh_wnode, child) == 40, "bvh_wnode layout");
_Static_assert(sizeof(bvh_tri4) == BVH_TRI4_SLOTS * sizeof(bvh_wnode), "bvh_tri4 takes whole node slots");
_Static_assert(offsetof(bvh_tri4, prim) == 144, "bvh_tri4 layout");
_Static_assert(sizeof(dev_prim) == 64, "dev_prim is 64 bytes");
_Static_assert(offsetof(dev_prim, type) == 48, "dev_prim ints at 48");
_Static_assert(sizeof(dev_material) == 208 && offsetof(dev_material, pattern) == 144 &&
               offsetof(dev_material, irid) == 176, "dev_material layout");
_Static_assert(sizeof(dev_light) == 128, "dev_light is 128 bytes");
_Static_assert(offsetof(dev_light, cos_falloff) == 80, "dev_light scalars at 80");
_Static_assert(sizeof(dev_warp) == 80, "dev_warp is 80 bytes");
_Static_assert(sizeof(dev_pattern) == 144 && offsetof(dev_pattern, params) == 80, "dev_pattern layout");
_Static_assert(sizeof(dev_map_entry) == 32, "dev_map_entry is 32 bytes");
_Static_assert(sizeof(dev_image) == 16, "dev_image is 16 bytes");
_Static_assert(sizeof(dev_emitter) == 16, "dev_emitter is 16 bytes");
_Static_assert(sizeof(dev_params) == 208, "dev_params is 208 bytes");
_Static_assert(sizeof(dev_fog) == 80 && offsetof(dev_fog, distance) == 48, "dev_fog layout");
_Static_assert(sizeof(dev_rainbow) == 80 && offsetof(dev_rainbow, jitter) == 48 && offsetof(dev_rainbow, pattern) == 64,
               "dev_rainbow layout");
_Static_assert(sizeof(dev_media) == 128 && offsetof(dev_media, method) == 80, "dev_media layout");
_Static_assert(sizeof(dev_sky) == 112 && offsetof(dev_sky, width) == 96, "dev_sky layout");
_Static_assert((int)OBJECT_NO_SHADOW == (int)OBJ_NO_SHADOW && (int)OBJECT_NO_IMAGE == (int)OBJ_NO_IMAGE &&
               (int)OBJECT_NO_REFLECTION == (int)OBJ_NO_REFLECTION && (int)OBJECT_HOLLOW == (int)OBJ_HOLLOW &&
               (int)OBJECT_DOUBLE_ILLUMINATE == (int)OBJ_DOUBLE_ILLUMINATE,
               "the kernels' object flags are scene.h's");
_Static_assert(offsetof(dev_params, width) == 96, "dev_params ints at 96");

/* A growing array of primitives, and for the top level their world boxes
 * (box is NULL in a mesh's list, whose triangles' corners give theirs). */
struct prim_list {
	dev_prim *p;
	bvh_box *box;
	int n, cap;
};

/* A mesh lowered once: its triangles in object space, in its BVH's order. */
struct lowered_mesh {
	int done;
	struct prim_list prims;
	bvh_tree bvh;
	float box[2][3];
	lower_bvh_stats stats;
};

/* Everything that grows while lowering. */
struct lowering {
	const lower_options *opt;
	const scene *s;
	struct prim_list top, planes;
	/* Records no BVH holds: PRIM_DATA, CSG leaves and programs; their indices
	 * are relative to this list until join puts it after every BVH's. */
	struct prim_list data;
	struct prim_list *target;   /* where shapes go: &top, or a CSG's leaves in data */
	dev_material *mats;
	int n_mats, cap_mats;
	lower_textures textures;
	float4 *normals;
	int n_normals, cap_normals;
	struct lowered_mesh *meshes;
	int n_degenerate;
	int *pattern_csg;           /* an object pattern's CSG (scene.csgs): its PRIM_CSG record in data, or -1 */
};

/* Lowering cannot go on without its arrays: running out of memory ends eclat. */
static void *xrealloc(void *p, size_t n)
{
	p = realloc(p, n ? n : 1);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	return p;
}

static void *xmalloc(size_t n)
{
	return xrealloc(NULL, n);
}

static void *grow(void *p, int *cap, size_t size)
{
	*cap = *cap ? 2 * *cap : 64;
	return xrealloc(p, (size_t)*cap * size);
}

static float4 f4(const double v[3], double w)
{
	return (float4){ (float)v[0], (float)v[1], (float)v[2], (float)w };
}

static int within_range(float v)
{
	return v >= -LOWER_FAR && v <= LOWER_FAR;   /* false for NaN */
}

static int all_in_range(const float *v, int n)
{
	for (int i = 0; i < n; i++)
		if (!within_range(v[i]))
			return 0;
	return 1;
}

/* The same for a vector of the scene, in double precision. */
static int vector_in_range(const double v[3])
{
	for (int k = 0; k < 3; k++)
		if (!(fabs(v[k]) <= LOWER_FAR))   /* false for NaN */
			return 0;
	return 1;
}

/* Colours past LOWER_FAR (rgb 1e39 is infinite in single precision) would turn
 * every path that meets them into infinity or NaN. */
static int material_in_range(const scene_material *m)
{
	return all_in_range(m->pigment, 5) && all_in_range(m->emission, 3);
}

/* ---- materials ---- */

static int add_material(struct lowering *lw, const scene_material *m, int local)
{
	if (lw->n_mats == lw->cap_mats)
		lw->mats = grow(lw->mats, &lw->cap_mats, sizeof *lw->mats);
	lw->mats[lw->n_mats] = lower_texture(&lw->textures, lw->s, m, local);
	if (m->interior_texture == 0 || local)
		return lw->n_mats++;
	lw->mats[lw->n_mats].flags |= MATERIAL_INTERIOR;   /* the next material is its inner side */
	if (lw->n_mats + 1 == lw->cap_mats)
		lw->mats = grow(lw->mats, &lw->cap_mats, sizeof *lw->mats);
	lw->mats[lw->n_mats + 1] = lower_interior_texture(&lw->textures, lw->s, m);
	lw->n_mats += 2;
	return lw->n_mats - 2;
}

void lower_blob_textures(struct lowering *lw, const scene_object *o, int mat)
{
	lw->mats[mat] = lower_texture_blob(&lw->textures, lw->s, o, &lw->mats[mat]);
}

/* ---- shapes ---- */

static void push_prim(struct prim_list *l, dev_prim p)
{
	if (l->n == l->cap)
		l->p = grow(l->p, &l->cap, sizeof p);
	l->p[l->n++] = p;
}

static bvh_box triangle_box(const dev_prim *p);

/* The top level's list keeps each primitive's box beside it for the builder. */
static void push_prim_box(struct prim_list *l, dev_prim p, const bvh_box *b)
{
	if (l->n == l->cap) {
		int cap = l->cap;
		l->p = grow(l->p, &cap, sizeof p);
		l->box = grow(l->box, &l->cap, sizeof *l->box);
	}
	l->box[l->n] = b ? *b : triangle_box(&p);
	l->p[l->n++] = p;
}

/* A double box rounded outward to floats. */
static bvh_box float_box(const double lo[3], const double hi[3])
{
	bvh_box b;
	for (int k = 0; k < 3; k++) {
		b.min[k] = nextafterf((float)lo[k], -INFINITY);
		b.max[k] = nextafterf((float)hi[k], INFINITY);
	}
	return b;
}

void lower_add_prim(struct lowering *lw, dev_prim p, int material, int object, const double lo[3],
                    const double hi[3])
{
	p.material = material;
	p.object = object;
	if (lw->target != &lw->top) {
		push_prim(lw->target, p);
		return;
	}
	int unbounded = p.type == PRIM_PLANE;   /* a plane, or a box past 1e9 (a quadric's) */
	for (int k = 0; lo && k < 3; k++)
		unbounded |= lo[k] <= -1e9 || hi[k] >= 1e9;
	if (unbounded) {
		push_prim(&lw->planes, p);
		return;
	}
	bvh_box b;
	if (lo)
		b = float_box(lo, hi);
	push_prim_box(&lw->top, p, lo ? &b : NULL);
}

int lower_add_data(struct lowering *lw, float4 a)
{
	push_prim(&lw->data, (dev_prim){ .a = a, .type = PRIM_DATA, .material = -1, .object = -1, .link = -1 });
	return lw->data.n - 1;
}

int lower_add_record(struct lowering *lw, float4 a, float4 b, float4 c)
{
	push_prim(&lw->data, (dev_prim){ .a = a, .b = b, .c = c, .type = PRIM_DATA, .material = -1, .object = -1,
	                                 .link = -1 });
	return lw->data.n - 1;
}

bool lower_in_csg(const struct lowering *lw)
{
	return lw->target != &lw->top;
}

int lower_local_rows(const xform *local_to_world, dev_prim *p)
{
	xform to_local;
	if (lower_invert(local_to_world, &to_local))
		return -1;
	float4 *rows[3] = { &p->a, &p->b, &p->c };
	for (int i = 0; i < 3; i++)
		*rows[i] = (float4){ (float)to_local.m[i][0], (float)to_local.m[i][1], (float)to_local.m[i][2],
		                     (float)to_local.m[i][3] };
	return 0;
}

int lower_local_rows_about(const xform *local_to_world, const double centre[3], dev_prim *p, float4 *c)
{
	xform to_local;
	if (lower_invert(local_to_world, &to_local))
		return -1;
	double cf[3];
	for (int k = 0; k < 3; k++)
		cf[k] = (float)centre[k];
	*c = (float4){ (float)cf[0], (float)cf[1], (float)cf[2], 0 };
	float4 *rows[3] = { &p->a, &p->b, &p->c };
	for (int i = 0; i < 3; i++) {
		const double *m = to_local.m[i];
		*rows[i] = (float4){ (float)m[0], (float)m[1], (float)m[2],
		                     (float)(m[0] * cf[0] + m[1] * cf[1] + m[2] * cf[2] + m[3]) };
	}
	return 0;
}

/* Three shading normals, and the corners' uv after them when there are uv
 * (the first normal's w says so: shape_triangle.cl's triangle_uv); returns
 * the index of the first three, for a smooth triangle's link. */
static int add_normals(struct lowering *lw, const double n[3][3], const double (*uv)[2])
{
	int first = lw->n_normals / 3;
	for (int k = 0; k < (uv ? 6 : 3); k++) {
		if (lw->n_normals == lw->cap_normals)
			lw->normals = grow(lw->normals, &lw->cap_normals, sizeof *lw->normals);
		lw->normals[lw->n_normals++] = k < 3 ? f4(n[k], k == 0 && uv ? 1 : 0)
		                                     : (float4){ (float)uv[k - 3][0], (float)uv[k - 3][1], 0, 0 };
	}
	return first;
}

/* A triangle into list, unless it has no area; normals (or NULL) make it
 * smooth; uv (or NULL), its corners' uv, make it smooth too (a flat one's
 * normals are its face's). */
static void add_triangle_uv_to(struct lowering *lw, struct prim_list *list, const double v[3][3],
                               const double (*normals)[3], const double (*uv)[2], int material, int object,
                               src_loc loc)
{
	double e1[3], e2[3];
	for (int k = 0; k < 3; k++) {
		e1[k] = v[1][k] - v[0][k];
		e2[k] = v[2][k] - v[0][k];
	}
	double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
	                e1[0] * e2[1] - e1[1] * e2[0] };
	if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
		if (lw->n_degenerate++ == 0)
			diag_warning(loc, "triangle with no area skipped");
		return;
	}
	dev_prim p = { .a = f4(v[0], 0), .b = f4(v[1], 0), .c = f4(v[2], 0), .type = PRIM_TRIANGLE,
	               .material = material, .object = object, .link = -1 };
	double face[3][3] = { { n[0], n[1], n[2] }, { n[0], n[1], n[2] }, { n[0], n[1], n[2] } };
	if (normals || uv) {
		p.type = PRIM_SMOOTH_TRIANGLE;
		p.link = add_normals(lw, normals ? normals : (const double (*)[3])face, uv);
	}
	if (list == &lw->top)
		push_prim_box(list, p, NULL);
	else
		push_prim(list, p);
}

static void add_triangle_to(struct lowering *lw, struct prim_list *list, const double v[3][3],
                            const double (*normals)[3], int material, int object, src_loc loc)
{
	add_triangle_uv_to(lw, list, v, normals, NULL, material, object, loc);
}

void lower_add_triangle(struct lowering *lw, const double v[3][3], const double (*normals)[3], int material,
                        int object, src_loc loc)
{
	add_triangle_to(lw, lw->target, v, normals, material, object, loc);
}

static double det3(const xform *t)
{
	const double (*m)[4] = t->m;
	return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
	       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
	       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

int lower_invert(const xform *t, xform *inv)
{
	double d = det3(t);
	if (fabs(d) < 1e-300)
		return -1;
	const double (*m)[4] = t->m;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
			inv->m[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / d;
		}
	for (int i = 0; i < 3; i++)
		inv->m[i][3] = -(inv->m[i][0] * m[0][3] + inv->m[i][1] * m[1][3] + inv->m[i][2] * m[2][3]);
	return 0;
}

void lower_background_alpha(const scene *s, dev_params *p)
{
	const float *bg = s->background, *ft = s->background_ft;
	float through = ft[0] * (0.297f * bg[0] + 0.589f * bg[1] + 0.114f * bg[2]) + ft[1];
	p->background.w = fminf(1.0f, fabsf(through));
	p->classic.x = ft[0] + ft[1];
}

static double ms_since(const struct timespec *t0)
{
	struct timespec t1;
	clock_gettime(CLOCK_MONOTONIC, &t1);
	return (t1.tv_sec - t0->tv_sec) * 1e3 + (t1.tv_nsec - t0->tv_nsec) * 1e-6;
}

/* A primitive's box: the one kept beside it in the top level's list, else
 * (a mesh's triangle) its corners'. */
static void box_of_prim(const void *ctx, int i, bvh_box *out)
{
	const struct prim_list *l = ctx;
	*out = l->box ? l->box[i] : triangle_box(&l->p[i]);
}

/* Puts p into the tree's leaf order, p[i] = old p[index[i]], in place by
 * following each cycle of the permutation: build_tree's fallback when there is
 * no memory for bvh_gather's copy, which is faster (the cycles go from cache
 * miss to cache miss). index is used up (each entry becomes its own position). */
static void permute(dev_prim *p, int *index, int n)
{
	for (int start = 0; start < n; start++) {
		if (index[start] == start)
			continue;
		dev_prim first = p[start];
		int j = start;
		while (index[j] != start) {
			int k = index[j];
			p[j] = p[k];
			index[j] = j;
			j = k;
		}
		p[j] = first;
		index[j] = j;
	}
}

/* Builds the chosen BVH over list and reorders list into its leaf order. */
static int build_tree(struct lowering *lw, struct prim_list *list, bvh_tree *t, lower_bvh_stats *st)
{
	struct timespec t0;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	int rc;
	lower_cache *cache = list != &lw->top ? lw->opt->cache : NULL;   /* a mesh's */
	if (cache && lower_cache_find(cache, lw->opt, list->p, list->n, t)) {
		rc = 0;
		cache = NULL;
	} else if (lw->opt->builder == LOWER_BVH_MEDIAN) {
		bvh_box *boxes = malloc((list->n ? list->n : 1) * sizeof *boxes);
		if (!boxes)
			return -1;
		for (int i = 0; i < list->n; i++)
			box_of_prim(list, i, &boxes[i]);
		rc = bvh_build_median(boxes, list->n, lw->opt->median_depth, t);
		free(boxes);
	} else if (list != &lw->top && lw->opt->layout == LOWER_LAYOUT_WIDE) {
		rc = bvh_build_leaves(box_of_prim, list, list->n, BVH_WIDE_BLOCK, t);
	} else {
		rc = bvh_build_fn(box_of_prim, list, list->n, t);
	}
	free(list->box);   /* the builder was their last reader */
	list->box = NULL;
	if (rc)
		return -1;
	if (cache)   /* before the permutation, which uses up prim_index */
		lower_cache_keep(cache, lw->opt, list->p, list->n, t);
	/* A copy in leaf order, or with no memory for one, the slower permutation
	 * in place. The copy (64 bytes a primitive) hardly raises the peak: the
	 * builder has just given back its records and the unused part of its
	 * node array, about as much. */
	dev_prim *ordered = bvh_gather(list->p, sizeof *list->p, t->prim_index, list->n);
	if (ordered) {
		free(list->p);
		list->p = ordered;
		list->cap = list->n;
	} else {
		permute(list->p, t->prim_index, list->n);
	}
	st->build_ms = ms_since(&t0);
	st->prims = list->n;
	st->nodes = t->n_nodes;
	st->depth = t->depth;
	st->sah_cost = t->sah_cost;
	for (int i = 0; i < t->n_nodes; i++)
		st->leaves += t->nodes[i].count > 0;
	st->bytes = (size_t)t->n_nodes * sizeof(bvh_node) + (size_t)list->n * sizeof(dev_prim);
	return 0;
}

/* Whether the kernels can intersect p in single precision: a triangle's
 * corners (a NaN corner would not show in its box), or its box and, for the
 * kinds that hold a map to their own space, the map's entries. */
static int in_range(const dev_prim *p, const bvh_box *b)
{
	const float *f = (const float *)&p->a;   /* a, b, c: twelve floats */
	if (p->type == PRIM_TRIANGLE || p->type == PRIM_SMOOTH_TRIANGLE)
		return all_in_range(f, 3) && all_in_range(f + 4, 3) && all_in_range(f + 8, 3);
	int rows = p->type != PRIM_SPHERE && p->type != PRIM_DATA && p->type != PRIM_CSG;
	if (!all_in_range(f, rows ? 12 : 4))
		return 0;
	for (int k = 0; b && k < 3; k++)
		if (!within_range(b->min[k]) || !within_range(b->max[k]))
			return 0;
	return 1;
}

/* A mesh's triangles in its own space, with the face textures it has. */
static int lower_mesh_once(struct lowering *lw, const scene *s, int index)
{
	struct lowered_mesh *lm = &lw->meshes[index];
	if (lm->done)
		return lm->done == -2 ? 1 : lm->done < 0 ? -1 : 0;
	const scene_mesh *m = &s->meshes[index];
	int first_mat = lw->n_mats, normals_before = lw->n_normals;
	for (int i = 0; i < m->n_mats; i++)
		if (!material_in_range(&m->mats[i])) {
			diag_warning(m->loc, "mesh skipped: a colour of one of its textures passes %g, too "
			             "much for the device's single precision", LOWER_FAR);
			lm->done = -2;
			return 1;
		}
	for (int i = 0; i < m->n_mats; i++)
		add_material(lw, &m->mats[i], 1);
	for (int f = 0; f < m->n_faces; f++) {
		double v[3][3], n[3][3];
		for (int k = 0; k < 3; k++)
			memcpy(v[k], m->v[m->face[f][k]], sizeof v[k]);
		int smooth = m->nrm && m->face_nrm;
		for (int k = 0; k < 3 && smooth; k++)
			memcpy(n[k], m->nrm[m->face_nrm[f][k]], sizeof n[k]);
		int fm = m->face_mat && m->face_mat[f] >= 0 && m->face_mat[f] < m->n_mats ? first_mat + m->face_mat[f] : -1;
		/* a mesh's uv only where a texture is uv_mapped: they cost three normals a face */
		double uv[3][2];
		int with_uv = s->uv_mapped && m->uv && m->face_uv;
		for (int k = 0; k < 3 && with_uv; k++)
			memcpy(uv[k], m->uv[m->face_uv[f][k]], sizeof uv[k]);
		/* object: the face, for tests and debugging; surfaces take the instance's */
		add_triangle_uv_to(lw, &lm->prims, v, smooth ? (const double (*)[3])n : NULL,
		                   with_uv ? (const double (*)[2])uv : NULL, fm, f, m->loc);
	}
	lm->stats = (lower_bvh_stats){ .mesh = index, .loc = m->loc };
	if (lm->prims.n == 0) {   /* degenerate geometry: warn and skip, as for a triangle */
		diag_warning(m->loc, "mesh with no triangle with an area skipped");
		lm->done = -2;
		return 1;
	}
	for (int i = 0; i < lm->prims.n; i++)   /* rays cross the mesh in its own space */
		if (!in_range(&lm->prims.p[i], NULL)) {
			diag_warning(m->loc, "mesh skipped: a vertex is not a number or lies past %g units, "
			             "too far for the device's single precision", LOWER_FAR);
			lm->done = -2;
			return 1;
		}
	if (build_tree(lw, &lm->prims, &lm->bvh, &lm->stats)) {
		fprintf(stderr, "eclat: out of memory building a mesh's BVH\n");
		lm->done = -1;
		return -1;
	}
	lm->stats.bytes += (size_t)(lw->n_normals - normals_before) * sizeof(float4);
	const bvh_node *root = &lm->bvh.nodes[0];
	float box[2][3] = { { root->min_x, root->min_y, root->min_z }, { root->max_x, root->max_y, root->max_z } };
	memcpy(lm->box, box, sizeof box);
	lm->done = 1;
	return 0;
}

static bvh_box world_box(const dev_prim *inst, const float box[2][3]);

/* A placed mesh: an instance in the top level, the world-to-mesh map in its rows;
 * link holds the mesh's index until the node arrays are joined. Its box is the
 * mesh's tree's, moved. */
int lower_mesh_instance(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	int once = lower_mesh_once(lw, s, o->mesh);
	if (once)
		return once < 0 ? -1 : 0;
	dev_prim p = { .type = PRIM_INSTANCE, .material = mat, .object = id, .link = o->mesh };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "mesh with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	if (lower_in_csg(lw)) {   /* a leaf: join() puts the mesh's root in its record */
		double d[3] = { 0, 0, 0 };
		shape_mesh_inside_dir(s, o, d);
		int mesh = o->mesh;
		float4 rec = { (float)d[0], (float)d[1], (float)d[2], 0 };
		memcpy(&rec.w, &mesh, sizeof mesh);
		p.type = PRIM_CSG_MESH;
		p.link = lower_add_data(lw, rec);
		push_prim(lw->target, p);
		return 0;
	}
	bvh_box b = world_box(&p, lw->meshes[o->mesh].box);
	push_prim_box(&lw->top, p, &b);
	return 0;
}

/* One scene object into primitives. One whose numbers the device's single
 * precision cannot hold (a coordinate past LOWER_FAR, which squares past
 * float's range in the intersection tests) is warned about and left out, as
 * degenerate geometry is; in double precision, evaluation saw nothing wrong. */
static int lower_object(struct lowering *lw, const scene *s, int id)
{
	const scene_object *o = &s->objects[id];
	const char *name = shape_of(o)->name;
	if (!material_in_range(&o->material)) {
		diag_warning(o->loc, "%s skipped: its colour passes %g, too much for the device's single "
		             "precision", name, LOWER_FAR);
		return 0;
	}
	int top = lw->top.n, planes = lw->planes.n;
	int rc = shape_of(o)->lower(lw, s, o, add_material(lw, &o->material, 0), id);
	int ok = 1;
	for (int i = top; ok && i < lw->top.n; i++)
		ok = in_range(&lw->top.p[i], &lw->top.box[i]);
	for (int i = planes; ok && i < lw->planes.n; i++)
		ok = in_range(&lw->planes.p[i], NULL);
	if (!ok) {
		diag_warning(o->loc, "%s skipped: too far from the origin, too large or too thin for the "
		             "device's single precision (a coordinate or scale past %g)", name, LOWER_FAR);
		lw->top.n = top;
		lw->planes.n = planes;
	}
	return rc;
}

/* ---- CSG ---- */

/* The box record of a CSG leaf (kernels/csg.cl's csg_box): its bounds [lo,
 * hi], grown by a margin that covers single precision's rounding of the
 * leaf's hits, which lie in it; a.w 1 when the leaf's inside lies in it too,
 * so that a point outside is outside the leaf without its inside test. A
 * disc's inside is a half space, a plane's, quadric's or poly's may be
 * unbounded, and the flat shapes have none. */
static dev_prim csg_leaf_box(const scene_object *o, const double lo[3], const double hi[3])
{
	dev_prim r = { .type = PRIM_DATA, .material = -1, .object = -1, .link = -1 };
	float box[2][4] = { { 0 } };
	for (int k = 0; k < 3; k++) {
		double pad = 1e-3 * (fabs(lo[k]) + fabs(hi[k]) + (hi[k] - lo[k])) + 1e-6;
		box[0][k] = lo[k] <= hi[k] ? (float)fmax(lo[k] - pad, -1e30) : 1.0f;   /* empty: a box no ray meets */
		box[1][k] = lo[k] <= hi[k] ? (float)fmin(hi[k] + pad, 1e30) : -1.0f;
	}
	switch (o->shape) {
	case SHAPE_SPHERE: case SHAPE_BOX: case SHAPE_CYLINDER: case SHAPE_CONE: case SHAPE_TORUS:
	case SHAPE_SUPERELLIPSOID: case SHAPE_BLOB: case SHAPE_LATHE: case SHAPE_SOR: case SHAPE_PRISM:
	case SHAPE_SPHERE_SWEEP: case SHAPE_TEXT: case SHAPE_ISOSURFACE: case SHAPE_HEIGHT_FIELD: case SHAPE_MESH:
	case SHAPE_JULIA_FRACTAL:
		box[0][3] = 1.0f;
		break;
	default:
		break;
	}
	memcpy(&r.a, box[0], sizeof box[0]);
	memcpy(&r.b, box[1], sizeof box[1]);
	return r;
}

/* A CSG object: its leaves and program in the data list (kernels/csg.cl),
 * one PRIM_CSG in the top level with the box of its program, or among the
 * unbounded primitives that every ray tests when that box is not bounded (an
 * inverse, a plane); an object pattern's in the data list, where no ray
 * meets it (lw->pattern_csg says where). A leaf that lowers to several primitives (a flat box's
 * triangles) is their union; one that lowers to none is inside nowhere. The
 * leaves rays may meet come first, clipped_by's after them (link: how many
 * come first). */
static int lower_csg(struct lowering *lw, const scene *s, int index)
{
	const scene_csg *g = &s->csgs[index];
	struct prim_list leaves = { 0 };
	int *first = xmalloc((g->n_leaves + 1) * sizeof *first), *last = xmalloc((g->n_leaves + 1) * sizeof *last);
	double (*lo)[3] = xmalloc((g->n_leaves + 1) * sizeof *lo), (*hi)[3] = xmalloc((g->n_leaves + 1) * sizeof *hi);
	int rc = 0, ok = 1;
	lw->target = &leaves;
	int n_seen = 0;   /* the leaves a ray may meet come first, clipped_by's after them */
	for (int pass = 0; pass < 2; pass++)
	for (int k = 0; k < g->n_leaves; k++) {
		const scene_object *o = &s->objects[g->first + k];
		if (o->clip != (pass == 1))
			continue;
		first[k] = last[k] = leaves.n;
		for (int j = 0; j < 3; j++) {
			lo[k][j] = INFINITY;
			hi[k][j] = -INFINITY;
		}
		if (!material_in_range(&o->material)) {
			diag_warning(o->loc, "%s skipped: its colour passes %g, too much for the device's single "
			             "precision", shape_of(o)->name, LOWER_FAR);
			continue;
		}
		if (shape_of(o)->lower(lw, s, o, add_material(lw, &o->material, 0), g->first + k))
			rc = -1;
		shape_of(o)->bounds(s, o, lo[k], hi[k]);
		last[k] = leaves.n;
		n_seen = pass == 0 ? leaves.n : n_seen;
	}
	lw->target = &lw->top;
	for (int i = 0; ok && i < leaves.n; i++)
		ok = in_range(&leaves.p[i], NULL);
	if (!ok)
		diag_warning(g->loc, "CSG object skipped: a part is too far from the origin, too large or too thin "
		             "for the device's single precision (a coordinate or scale past %g)", LOWER_FAR);
	dev_prim *boxes = xmalloc((leaves.n + 1) * sizeof *boxes);   /* a box a leaf, in the leaves' order */
	for (int k = 0; k < g->n_leaves; k++)
		for (int j = first[k]; j < last[k]; j++)
			boxes[j] = csg_leaf_box(&s->objects[g->first + k], lo[k], hi[k]);
	csg_prog p = { 0 };
	for (int i = 0; i < g->n_ops; i++) {
		int op = csg_op_code(g->ops[i]), arg = csg_op_arg(g->ops[i]);
		if (op != CSG_LEAF) {
			csg_push(&p, op, arg);
			continue;
		}
		if (arg >= g->n_leaves || first[arg] == last[arg]) {
			csg_push(&p, CSG_LEAF, CSG_NO_LEAF);
			continue;
		}
		for (int j = first[arg]; j < last[arg]; j++) {
			csg_push(&p, boxes[j].a.w != 0 ? CSG_LEAF_BOXED : CSG_LEAF, j);
			if (j > first[arg])
				csg_push(&p, CSG_UNION, 2);
		}
	}
	if (rc == 0 && ok && csg_depth(p.ops, p.n) > CSG_STACK) {
		diag_error(g->loc, "this CSG object nests deeper than the %d levels the kernels can classify",
		           CSG_STACK);
		rc = -1;
	}
	dev_prim *nodes = NULL;
	int n_nodes = 0, root = CSG_NO_TREE, *list = NULL;
	if (rc == 0 && ok && lower_csg_tree(boxes, n_seen, &nodes, &n_nodes, &list, &root) > CSG_TREE_STACK) {
		diag_error(g->loc, "this CSG object has more parts than the %d levels of their tree the kernels can "
		           "walk", CSG_TREE_STACK);
		rc = -1;
	}
	csg_prog run = { 0 };   /* the program as the kernels run it, when it is not too deep; skips need the tree */
	if (rc == 0 && ok && lower_csg_program(p.ops, p.n, boxes, root == CSG_NO_TREE ? 0 : n_seen, &run) <= CSG_STACK) {
		free(p.ops);
		p = run;
	} else {
		free(run.ops);
	}
	double blo[3], bhi[3];
	csg_bounds(g->ops, g->n_ops, g->n_leaves, (const double (*)[3])lo, (const double (*)[3])hi, blo, bhi);
	int empty = blo[0] > bhi[0] || blo[1] > bhi[1] || blo[2] > bhi[2];
	if (rc == 0 && ok && !empty && leaves.n > 0) {
		int leaf_first = lw->data.n;
		for (int i = 0; i < leaves.n; i++)
			push_prim(&lw->data, leaves.p[i]);
		int prog_first = lw->data.n;
		for (int i = 0; i < p.n; i += CSG_OPS_PER_RECORD) {   /* in a, b, c: the type stays PRIM_DATA */
			dev_prim r = { .type = PRIM_DATA, .material = -1, .object = -1, .link = -1 };
			int n = p.n - i < CSG_OPS_PER_RECORD ? p.n - i : CSG_OPS_PER_RECORD;
			memcpy(&r, p.ops + i, n * sizeof *p.ops);
			push_prim(&lw->data, r);
		}
		int box_first = lw->data.n;   /* clipped_by's last */
		for (int j = 0; j < leaves.n; j++)
			push_prim(&lw->data, boxes[j]);
		int node_first = lw->data.n;
		for (int j = 0; j < n_nodes; j++)
			push_prim(&lw->data, nodes[j]);
		int list_first = lw->data.n;
		for (int i = 0; list && i < n_seen; i += CSG_OPS_PER_RECORD) {   /* as the program's records */
			dev_prim r = { .type = PRIM_DATA, .material = -1, .object = -1, .link = -1 };
			int n = n_seen - i < CSG_OPS_PER_RECORD ? n_seen - i : CSG_OPS_PER_RECORD;
			memcpy(&r, list + i, n * sizeof *list);
			push_prim(&lw->data, r);
		}
		int head[4] = { leaf_first, leaves.n, prog_first, p.n }, tree[4] = { box_first, node_first, root, list_first };
		dev_prim c = { .type = PRIM_CSG, .material = leaves.p[0].material, .object = g->first, .link = n_seen };
		memcpy(&c.a, head, sizeof head);
		memcpy(&c.b, tree, sizeof tree);
		int bounded = 1;
		for (int k = 0; k < 3; k++)
			bounded &= blo[k] > -1e9 && bhi[k] < 1e9;
		if (g->pattern) {   /* no ray meets it: only object patterns ask its inside */
			lw->pattern_csg[index] = lw->data.n;
			push_prim(&lw->data, c);
		} else if (bounded) {
			bvh_box b = float_box(blo, bhi);
			push_prim_box(&lw->top, c, &b);
		} else {
			push_prim(&lw->planes, c);
		}
	}
	free(p.ops);
	free(boxes);
	free(nodes);
	free(list);
	free(leaves.p);
	free(first);
	free(last);
	free(lo);
	free(hi);
	return rc;
}

/* ---- lights ---- */

/* A light whose numbers single precision cannot hold is left out, named. */
static int light_in_range(const scene_light *l)
{
	const double *v[] = { l->position, l->point_at, l->axis1, l->axis2 };
	int ok = all_in_range(l->color, 3);
	for (int i = 0; i < 4 && ok; i++)
		ok = vector_in_range(v[i]);
	if (!ok)
		diag_warning(l->loc, "light_source skipped: a position or colour passes %g, too much for "
		             "the device's single precision", LOWER_FAR);
	return ok;
}

static dev_light lower_light(const scene_light *l)
{
	double dir[3] = { l->point_at[0] - l->position[0], l->point_at[1] - l->position[1],
	                  l->point_at[2] - l->position[2] };
	double len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
	for (int i = 0; i < 3; i++)
		dir[i] = len > 0 ? dir[i] / len : (i == 2);
	double col[3] = { l->color[0], l->color[1], l->color[2] };
	double falloff = fmax(l->falloff, l->radius);
	return (dev_light){
		.position = f4(l->position, l->fade_distance),
		.color = f4(col, l->fade_power),
		.axis1 = f4(l->axis1, l->area),
		.axis2 = f4(l->axis2, l->area && l->circular),
		.spot = f4(dir, cos(l->radius * M_PI / 180)),
		.cos_falloff = (float)cos(falloff * M_PI / 180),
		.tightness = l->tightness,
		.kind = l->kind == LIGHT_SPOT ? LIGHT_KIND_SPOT : l->kind == LIGHT_PARALLEL ? LIGHT_KIND_PARALLEL
		                                                                          : LIGHT_KIND_POINT,
		.shadowless = l->shadowless,
		.grid = { l->area ? l->size1 : 0, l->area ? l->size2 : 0, l->adaptive, l->orient },
		.media_attenuation = l->media_attenuation,
		.no_media_interaction = l->no_media_interaction,
	};
}

static int lower_camera(const scene *s, dev_params *p)
{
	const scene_camera *c = &s->camera;
	const double *v[] = { c->location, c->direction, c->right, c->up, c->focal_point };
	for (int i = 0; i < 5; i++)
		if (!vector_in_range(v[i])) {
			diag_error(c->loc, "the camera's vectors pass %g, too much for the device's "
			           "single precision: bring the scene nearer the origin", LOWER_FAR);
			return -1;
		}
	const double angles[3] = { c->angle, c->h_angle, c->v_angle };
	if (!vector_in_range(angles)) {
		diag_error(c->loc, "the camera's angle passes %g degrees, too much for the device's single "
		           "precision", LOWER_FAR);
		return -1;
	}
	const float *sky = s->has_sky ? s->sky : s->background;
	if (!all_in_range(sky, 3)) {
		diag_error(SRC_NOWHERE, "the %s colour passes %g, too much for the device's single "
		           "precision", s->has_sky ? "sky_sphere" : "background", LOWER_FAR);
		return -1;
	}
	p->cam_location = f4(c->location, 0);
	p->cam_direction = f4(c->direction, 0);
	double deg = M_PI / 180;
	p->cam_right = f4(c->right, (c->type == CAMERA_SPHERICAL ? c->h_angle : c->angle) * deg);
	p->cam_up = f4(c->up, c->v_angle * deg);
	const float *bg = s->background;
	p->background = (float4){ bg[0], bg[1], bg[2], 0 };
	/* POV-Ray blurs only with blur_samples, and a negative aperture as its opposite */
	double aperture = c->blur_samples > 0 && c->type != CAMERA_MESH ? fabs(c->aperture) : 0;
	p->lens = (float4){ (float)aperture, (float)(c->focal_distance > 0 ? c->focal_distance : 1), (float)c->type, 0 };
	return 0;
}

/* The local-to-world map of an ellipsoid or instance, whose rows hold the inverse. */
static xform local_to_world(const dev_prim *p)
{
	xform to_local, to_world;
	const float4 *rows[3] = { &p->a, &p->b, &p->c };
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++)
			to_local.m[i][j] = ((const float *)rows[i])[j];
	lower_invert(&to_local, &to_world);
	return to_world;
}

/* The world box of an instance: the mesh's box with its eight corners moved. */
static bvh_box world_box(const dev_prim *inst, const float box[2][3])
{
	xform to_world = local_to_world(inst);
	bvh_box b = { { 1e30f, 1e30f, 1e30f }, { -1e30f, -1e30f, -1e30f } };
	for (int c = 0; c < 8; c++) {
		double p[3] = { box[c & 1][0], box[(c >> 1) & 1][1], box[(c >> 2) & 1][2] }, w[3];
		scene_xform_point(&to_world, p, w);
		for (int k = 0; k < 3; k++) {
			b.min[k] = fminf(b.min[k], (float)w[k]);
			b.max[k] = fmaxf(b.max[k], (float)w[k]);
		}
	}
	return b;
}

static bvh_box triangle_box(const dev_prim *p)
{
	bvh_box b;
	float v[3][3] = { { p->a.x, p->a.y, p->a.z },
	                  { p->b.x, p->b.y, p->b.z },
	                  { p->c.x, p->c.y, p->c.z } };
	/* Comparisons, not fminf: that is a library call without -ffast-math, and
	 * twelve of them per triangle took 1.2 of the bunny's 28 ms of build.
	 * in_range has turned away triangles with a NaN corner. */
	for (int k = 0; k < 3; k++) {
		float lo = v[0][k] < v[1][k] ? v[0][k] : v[1][k], hi = v[0][k] > v[1][k] ? v[0][k] : v[1][k];
		b.min[k] = v[2][k] < lo ? v[2][k] : lo;
		b.max[k] = v[2][k] > hi ? v[2][k] : hi;
	}
	return b;
}

/* A record's indices into the data list made absolute: a shape's link to its
 * PRIM_DATA record, a CSG's first leaf, program, leaf box, tree node and
 * tree list (its tree's references count from those). */
static void relocate(dev_prim *p, int base)
{
	switch (p->type) {
	case PRIM_TRIANGLE: case PRIM_SMOOTH_TRIANGLE: case PRIM_SPHERE: case PRIM_PLANE: case PRIM_INSTANCE:
	case PRIM_DATA:
		return;   /* their links are emitters, normals or roots */
	case PRIM_CSG: {
		int v[4];
		memcpy(v, &p->a, sizeof v);
		v[0] += base;
		v[2] += base;
		memcpy(&p->a, v, sizeof v);
		memcpy(v, &p->b, sizeof v);
		v[0] += base;
		v[1] += base;
		v[3] += base;
		memcpy(&p->b, v, sizeof v);
		return;
	}
	default:
		if (p->link >= 0)
			p->link += base;
	}
}

/* The top level's BVH, then one node array and one primitive array for all:
 * each mesh's nodes and triangles are moved after the top level's, and its
 * instances point at its root. */
static int join(struct lowering *lw, const scene *s, lower_result *out)
{
	bvh_tree top;
	out->stats = calloc(1 + s->n_meshes, sizeof *out->stats);
	if (!out->stats)
		return -1;
	out->stats[0].mesh = -1;
	out->stats[0].loc = SRC_NOWHERE;
	if (build_tree(lw, &lw->top, &top, &out->stats[0]))
		return -1;
	out->n_stats = 1;
	int n_nodes = top.n_nodes, n_prims = lw->top.n + lw->planes.n;
	int *node_base = xmalloc((s->n_meshes + 1) * sizeof *node_base);
	int *prim_base = xmalloc((s->n_meshes + 1) * sizeof *prim_base);
	for (int m = 0; m < s->n_meshes; m++) {
		node_base[m] = n_nodes;
		prim_base[m] = n_prims;
		if (lw->meshes[m].done > 0) {
			n_nodes += lw->meshes[m].bvh.n_nodes;
			n_prims += lw->meshes[m].prims.n;
			out->stats[out->n_stats++] = lw->meshes[m].stats;
		}
	}
	out->nodes = xmalloc(n_nodes * sizeof *out->nodes);
	out->prims = xmalloc((n_prims + lw->data.n) * sizeof *out->prims);
	memcpy(out->nodes, top.nodes, top.n_nodes * sizeof *top.nodes);
	if (lw->top.n)      /* an empty list's p is NULL, which memcpy must not get */
		memcpy(out->prims, lw->top.p, lw->top.n * sizeof *lw->top.p);
	if (lw->planes.n)
		memcpy(out->prims + lw->top.n, lw->planes.p, lw->planes.n * sizeof *lw->planes.p);
	for (int m = 0; m < s->n_meshes; m++) {
		struct lowered_mesh *lm = &lw->meshes[m];
		if (lm->done <= 0)
			continue;
		for (int i = 0; i < lm->bvh.n_nodes; i++) {
			bvh_node n = lm->bvh.nodes[i];
			n.left_first += n.count > 0 ? prim_base[m] : node_base[m];
			out->nodes[node_base[m] + i] = n;
		}
		memcpy(out->prims + prim_base[m], lm->prims.p, lm->prims.n * sizeof *lm->prims.p);
	}
	for (int i = 0; i < lw->top.n; i++)
		if (out->prims[i].type == PRIM_INSTANCE)
			out->prims[i].link = node_base[out->prims[i].link];
	int data_base = n_prims;
	if (lw->data.n)
		memcpy(out->prims + data_base, lw->data.p, lw->data.n * sizeof *lw->data.p);
	n_prims += lw->data.n;
	for (int i = 0; i < lw->top.n + lw->planes.n; i++)
		relocate(&out->prims[i], data_base);
	for (int i = data_base; i < n_prims; i++)
		relocate(&out->prims[i], data_base);
	for (int i = data_base; i < n_prims; i++)   /* CSG leaves' meshes: their roots */
		if (out->prims[i].type == PRIM_CSG_MESH) {
			float4 *rec = &out->prims[out->prims[i].link].a;
			int mesh;
			memcpy(&mesh, &rec->w, sizeof mesh);
			memcpy(&rec->w, &node_base[mesh], sizeof mesh);
		}
	out->n_nodes = n_nodes;
	out->n_prims = lw->top.n;
	out->n_planes = lw->planes.n;
	out->n_all_prims = n_prims;
	free(node_base);
	free(prim_base);
	bvh_free(&top);
	return 0;
}

static int check_depths(const lower_result *out)
{
	for (int i = 0; i < out->n_stats; i++)
		if (out->stats[i].depth > BVH_STACK_SIZE) {
			diag_error(out->stats[i].loc, "a BVH is %d levels deep, more than the %d the kernels can traverse",
			           out->stats[i].depth, BVH_STACK_SIZE);
			return -1;
		}
	return 0;
}

static int cmp_int(const void *a, const void *b)
{
	int x = *(const int *)a, y = *(const int *)b;
	return (x > y) - (x < y);
}

/* Where a placed mesh keeps its root: an instance in its link, a CSG's mesh
 * leaf in its record's a.w; NULL for any other primitive. */
static int *mesh_root(lower_result *out, int i)
{
	dev_prim *p = &out->prims[i];
	if (p->type == PRIM_INSTANCE)
		return &p->link;
	return p->type == PRIM_CSG_MESH ? (int *)&out->prims[p->link].a.w : NULL;
}

/* The wide layout: every tree converted once (a mesh placed many times
 * included), the instances and CSG mesh leaves pointed at their meshes' wide
 * roots. The binary nodes stay for --stats and the tests. */
static int widen_trees(lower_result *out)
{
	int *roots = xmalloc((out->n_all_prims + 1) * sizeof *roots), n_roots = 0;
	for (int i = 0; i < out->n_all_prims; i++)
		if (mesh_root(out, i))
			roots[1 + n_roots++] = *mesh_root(out, i);
	qsort(roots + 1, n_roots, sizeof *roots, cmp_int);
	int unique = 0;
	for (int i = 0; i < n_roots; i++)
		if (unique == 0 || roots[1 + i] != roots[unique])
			roots[1 + unique++] = roots[1 + i];
	n_roots = 1 + unique;
	roots[0] = out->n_prims > 0 ? 0 : -1;
	bvh_wide w;
	int rc = bvh_widen(out->nodes, roots, n_roots, out->prims, 1, &w);
	if (rc == 0 && w.max_stack > BVH_STACK_SIZE) {
		diag_error(SRC_NOWHERE, "the wide BVH needs a traversal stack of %d, more than the kernels' %d",
		           w.max_stack, BVH_STACK_SIZE);
		rc = -1;
	} else if (rc != 0) {
		fprintf(stderr, "eclat: the BVH cannot be converted to the wide layout "
		                "(out of memory, or more than %d primitives)\n", 1 << BVH_WIDE_FIRST_BITS);
	}
	for (int i = 0; rc == 0 && i < out->n_all_prims; i++)
		if (mesh_root(out, i)) {
			int *r = bsearch(mesh_root(out, i), roots + 1, n_roots - 1, sizeof *roots, cmp_int);
			*mesh_root(out, i) = w.roots[r - roots];
		}
	free(roots);
	if (rc != 0) {
		bvh_wide_free(&w);
		return -1;
	}
	out->wnodes = w.nodes;
	out->n_wnodes = w.n_nodes - BVH_TRI4_SLOTS * w.n_blocks;
	out->n_wblocks = w.n_blocks;
	out->dev_nodes = w.nodes;
	out->dev_node_bytes = (size_t)w.n_nodes * sizeof *w.nodes;
	free(w.roots);
	return 0;
}

const char *lower_kernel_options(const lower_result *lr)
{
	static _Thread_local char buf[256];
	int k = lr->kernels;
	char levels[32] = "";
	if (lr->functions && lr->function_levels > 1)
		snprintf(levels, sizeof levels, " -DFUNCTION_LEVELS=%d", lr->function_levels);
	snprintf(buf, sizeof buf, "-cl-std=CL1.2%s%s%s%s%s%s%s%s%s", lr->layout == LOWER_LAYOUT_WIDE ? " -DBVH_WIDE=1" : "",
	         lr->functions ? " -DSCENE_FUNCTIONS=1" : "", levels, lr->object_patterns ? " -DOBJECT_PATTERNS=1" : "",
	         k ? " -DKERNELS_SOME=1" : "",
	         k & LOWER_KERNELS_PATH ? " -DKERNELS_PATH=1" : "", k & LOWER_KERNELS_WHITTED ? " -DKERNELS_WHITTED=1" : "",
	         k & LOWER_KERNELS_WHITTED_AA1 ? " -DKERNELS_WHITTED_AA1=1" : "",
	         k & LOWER_KERNELS_WHITTED_AA2 ? " -DKERNELS_WHITTED_AA2=1" : "");
	return buf;
}

/* Each object pattern's params[0].x, its object's index in scene.csgs until
 * now, becomes the int bits of that object's PRIM_CSG record, which join put
 * after every BVH's primitives, or -1 for none. The kernels classify points
 * for them only when the scene has one (OBJECT_PATTERNS): the CSG code
 * under pattern_at costs every other scene's cold build a quarter more. */
static void place_object_patterns(const struct lowering *lw, const scene *s, lower_result *out)
{
	int data_base = out->n_all_prims - lw->data.n;
	for (int i = 0; i < out->textures.n_patterns; i++) {
		dev_pattern *pt = &out->textures.patterns[i];
		if (pt->kind != PATTERN_OBJECT)
			continue;
		out->object_patterns = 1;
		int g = (int)pt->params[0].x;
		int rec = g >= 0 && g < s->n_csgs && lw->pattern_csg[g] >= 0 ? data_base + lw->pattern_csg[g] : -1;
		memcpy(&pt->params[0].x, &rec, sizeof rec);
	}
}

int lower_scene(const scene *s, const lower_options *opt, lower_result *out)
{
	memset(out, 0, sizeof *out);
	static const lower_options defaults = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_DEFAULT, 0, 0, 0, NULL, 0 };
	struct lowering lw = { .opt = opt ? opt : &defaults, .s = s };
	lw.target = &lw.top;
	lw.meshes = calloc(s->n_meshes + 1, sizeof *lw.meshes);
	lw.pattern_csg = xmalloc((s->n_csgs + 1) * sizeof *lw.pattern_csg);
	for (int g = 0; g < s->n_csgs; g++)
		lw.pattern_csg[g] = -1;   /* an empty object, or one left out: inside nowhere */
	if (!lw.meshes) {
		free(lw.pattern_csg);
		return -1;
	}
	int rc = 0;
	for (int i = 0; i < s->n_objects; i++) {
		int g = s->objects[i].csg - 1;
		if (g >= 0 && g < s->n_csgs && s->csgs[g].first <= i && i < s->csgs[g].first + s->csgs[g].n_leaves) {
			if (i == s->csgs[g].first && lower_csg(&lw, s, g))
				rc = -1;
		} else if (lower_object(&lw, s, i)) {
			rc = -1;
		}
	}
	if (lw.n_degenerate > 1)
		diag_warning(SRC_NOWHERE, "%d triangles with no area skipped in all", lw.n_degenerate);

	out->lights = xmalloc(s->n_lights * sizeof *out->lights);
	for (int i = 0; i < s->n_lights; i++)
		if (light_in_range(&s->lights[i]))
			out->lights[out->n_lights++] = lower_light(&s->lights[i]);
	out->params.sky = -1;   /* the sky's layers, as materials side by side */
	for (int i = 0; s->has_sky && i < s->n_sky_layers; i++) {
		int m = add_material(&lw, &s->sky_layers[i], 0);
		out->params.sky = i == 0 ? m : out->params.sky;
		out->params.sky_layers = i + 1;
	}
	xform world = scene_xform_identity();
	int n_atmosphere, atmosphere = lower_media(&lw.textures, s, s->atmosphere, &world, &n_atmosphere);
	/* the camera's normal, in the space of its image points: only its own transformations */
	int camera_normal = s->camera.normal >= 0 && s->camera.normal < s->n_pigments
	                    ? lower_texture_pigment(&lw.textures, s, s->camera.normal) : -1;
	lower_rainbows(&lw.textures, s, out);
	lower_textures_append(&lw.textures, &lw.mats, &lw.n_mats);
	out->materials = lw.mats;
	out->n_materials = lw.n_mats;
	out->textures = lw.textures;
	out->object_flags = xmalloc(s->n_objects * sizeof *out->object_flags);
	for (int i = 0; i < s->n_objects; i++)
		out->object_flags[i] = s->objects[i].flags;
	out->n_objects = s->n_objects;
	int shadows_pass = lw.textures.see_through;
	for (int i = 0; i < s->n_objects; i++)
		shadows_pass |= (s->objects[i].flags & OBJ_NO_SHADOW) != 0;
	out->params.scene_flags = (shadows_pass ? SCENE_SHADOWS_PASS : 0) | (s->sky_legacy ? SCENE_SKY_LEGACY : 0) |
	                          (lw.textures.n_media ? SCENE_MEDIA : 0) | (lw.textures.uses_uv ? SCENE_UV : 0);
	out->normals = lw.normals;
	out->n_normals = lw.n_normals;
	if (lower_camera(s, &out->params) || lower_fogs(s, out) ||
	    lower_camera_mesh(s, lw.opt->width, lw.opt->height, out) || lower_camera_lens(s, out))
		rc = -1;
	out->params.n_fogs = out->n_fogs;
	out->params.atmosphere = atmosphere;
	out->params.n_atmosphere = n_atmosphere;
	out->params.camera_solids = out->n_fogs || out->n_rainbows || out->textures.n_media ? lower_camera_solids(s) : 0;
	out->params.camera_normal = camera_normal;
	lower_media_warn_open(s);
	if (rc == 0 && join(&lw, s, out))
		rc = -1;
	if (rc == 0)
		rc = check_depths(out);
	out->layout = lw.opt->layout;
	out->kernels = lw.opt->kernels;
	out->dev_nodes = out->nodes;
	out->dev_node_bytes = (size_t)out->n_nodes * sizeof *out->nodes;
	if (rc == 0 && out->layout == LOWER_LAYOUT_WIDE)
		rc = widen_trees(out);
	if (rc == 0 && lower_emitters(out) < 0)
		rc = -1;
	if (rc == 0 && lower_sky(out) < 0)
		rc = -1;
	int *roots = lower_function_roots(&out->textures, s);
	out->functions = lower_function_source(s, roots);
	out->function_levels = lower_function_levels(s);
	free(roots);
	if (s->n_functions > 0 && !out->functions)
		rc = -1;   /* said why, or out of memory: no kernel without its functions */
	if (rc == 0)
		place_object_patterns(&lw, s, out);
	free(lw.pattern_csg);
	for (int m = 0; m < s->n_meshes; m++) {
		free(lw.meshes[m].prims.p);
		bvh_free(&lw.meshes[m].bvh);
	}
	free(lw.meshes);
	if (lw.opt->cache)
		lower_cache_sweep(lw.opt->cache);
	free(lw.top.p);
	free(lw.top.box);
	free(lw.planes.p);
	free(lw.data.p);
	return rc;
}

void lower_free(lower_result *r)
{
	free(r->functions);
	free(r->nodes);
	free(r->wnodes);
	free(r->normals);
	free(r->stats);
	free(r->prims);
	free(r->materials);
	lower_textures_free(&r->textures);
	free(r->object_flags);
	free(r->lights);
	free(r->fogs);
	free(r->rainbows);
	free(r->camera_rays);
	free(r->emitters);
	free(r->sky_cdf);
	memset(r, 0, sizeof *r);
}
