/* eval_hfield.c: height_field { TYPE "file" [gamma G] [premultiplied B] |
 * function W, H { EXPRESSION } [smooth] [water_level L] [hierarchy B] }, POV-Ray
 * 3.7's height field, made here into the triangles POV-Ray intersects: a grid
 * of the image's pixels over [0, 1] in x and z, each pixel's height in y, and
 * each cell two triangles on the diagonal from (x + 1, z) to (x, z + 1)
 * (heightfield.cpp). It becomes a mesh of scene.meshes (src/shape_height_field.c
 * places it). As in POV-Ray:
 *  - the image's bottom row is z = 0;
 *  - a height is a 16-bit value over 65536: an indexed image's palette index
 *    times 256 (a PNG's or a GIF's, through libpng or giflib); a POT file's
 *    (Fractint's: a GIF twice as wide as its heights) left half's index times
 *    256 plus its right half's (gif.cpp); an 8-bit colour image's red is its
 *    high byte and green its low byte; a grey image, or one of more than 8 bits,
 *    gives its grey value times 65535 (imageutil.cpp's image_height_at);
 *  - a function's image has the function's value at x = column / (W - 1) and
 *    y = row / (H - 1), z = 0, the top row first, clamped to [0, 1] as a 16-bit
 *    grey image clamps it (Make_Pattern_Image); a pigment function's is a
 *    16-bit colour image, whose grey gives the height;
 *  - smooth: each point's normal is the mean of the four triangles' about it in
 *    the raw grid (smooth_height_field);
 *  - water_level L: nothing below L is drawn (the triangles wholly below). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"
#include "image.h"

#define MAX_TEXELS (1L << 24)   /* 4096 x 4096 grid points: 33 million triangles */

static const char *const types[] = { "gif", "tga", "pot", "png", "pgm", "ppm", "jpeg", "tiff", "sys", "exr", "hdr",
                                     "iff", "bmp" };

/* What a grid point takes, from its height to its two triangles in the mesh
 * and their share of the device's triangles and BVH: about 128 bytes; a
 * smooth one's normal and its triangles' normal indices 48 more, claimed once
 * smooth is read (after the grid). */
#define BYTES_PER_POINT 128.0
#define SMOOTH_BYTES_PER_POINT 48.0

static int claim_grid(struct eval *e, src_loc loc, int w, int h)
{
	char what[96];
	snprintf(what, sizeof what, "a height field of %d x %d points", w, h);
	return eval_memory_claim(e, loc, (double)w * h * BYTES_PER_POINT, what);
}

/* The grid's heights (0 .. 65535), bottom row first, from the image file. */
static int image_heights(struct eval *e, const ast_node *at, const char *name, bool pot, double **h, int *w,
                         int *hh)
{
	char *path = eval_find_file(e, at->loc.file, name);
	const char *use = path ? path : name;
	image_data d;
	char why[512];
	if (eval_access(e, use, false, at->loc, "a height_field")) {
		free(path);
		return -1;
	}
	image_limits lim = { MAX_TEXELS, e->opt->mesh_time_limit, eval_memory_left(e) };
	if (image_read(use, &lim, &d, why, sizeof why)) {
		eval_error(e, at->loc, "cannot read height field image '%s': %s", name, why);
		free(path);
		return -1;
	}
	unsigned char *index = NULL;
	int iw, ih, kind = image_indices(use, &lim, &index, &iw, &ih);
	if (!kind || iw != d.width || ih != d.height) {
		free(index);
		index = NULL;
	}
	free(path);
	if (pot && (!index || kind != IMAGE_INDICES_GIF || d.width % 2 != 0)) {   /* POV-Ray: "Invalid width for POT file" */
		eval_error(e, at->loc, "'%s' is no POT file (a GIF twice as wide as its heights)", name);
		free(d.rgba);
		free(index);
		return -1;
	}
	int half = pot ? d.width / 2 : 0;   /* a POT's right half holds its heights' low bytes */
	d.width -= half;
	if (claim_grid(e, at->loc, d.width, d.height)) {
		free(d.rgba);
		free(index);
		return -1;
	}
	*w = d.width;
	*hh = d.height;
	*h = eval_xrealloc(NULL, (size_t)d.width * d.height * sizeof **h);
	bool grey = d.channels <= 2, deep = d.bits > 8;
	for (int z = 0; z < d.height; z++)
		for (int x = 0; x < d.width; x++) {
			size_t row = (size_t)(d.height - 1 - z) * (d.width + half), at = row + x;
			const float *p = d.rgba + 4 * at;
			double v = pot ? index[at] * 256.0 + index[at + half]
			         : index ? index[at] * 256.0   /* POV-Ray's 256, not 257: its 3.6 heights */
			         : grey ? p[0] * 65535.0
			         : deep ? (0.297 * p[0] + 0.589 * p[1] + 0.114 * p[2]) * 65535.0   /* POV-Ray's Greyscale */
			                : (p[0] * 256.0 + p[1]) * 255.0;
			(*h)[(size_t)z * d.width + x] = floor(v < 0 ? 0 : v > 65535 ? 65535 : v);
		}
	free(d.rgba);
	free(index);
	return 0;
}

/* A function's pattern and pigment calls, through the device (a height
 * field's points are known at once, so each call is one launch for them all). */
struct hf_calls {
	struct eval *e;
	src_loc loc;
};

static int hf_pattern(void *ctx, int pigment, bool colour, int n, const double *p, double *out)
{
	struct hf_calls *c = ctx;
	return eval_pattern_points(c->e, c->loc, pigment, colour, n, p, out);
}

#define HF_BLOCK 4096   /* grid points evaluated together */

/* The heights of one block of points a (three doubles a point): a float
 * function's value as a 16-bit grey image keeps it (clamped, rounded); a
 * pigment's colour as a 16-bit RGBA image keeps it, each channel cut to 16
 * bits, then its grey (image_height_at). */
static int hf_block(struct eval *e, const ast_node *fn, int f, const scene_material *pm, int n, const double *a,
                    double *v)
{
	struct hf_calls calls = { e, fn->loc };
	if (f >= 0) {
		if (scene_function_eval_many(e->s, f, n, a, v, e->opt->pattern_at ? hf_pattern : NULL, &calls))
			return -1;
		for (int i = 0; i < n; i++) {
			double x = (float)v[i];
			x = isnan(x) ? 0 : x < 0 ? 0 : x > 1 ? 1 : x;
			v[i] = floor(x * 65535.0 + 0.5);
		}
		return 0;
	}
	double *c = eval_xrealloc(NULL, (size_t)n * 5 * sizeof *c);
	for (int i = 0; i < n; i++)
		for (int k = 0; k < 5; k++)
			c[5 * i + k] = pm->pigment[k];
	int rc = pm->pattern >= 0 ? eval_pattern_points(e, fn->loc, pm->pattern, true, n, a, c) : 0;
	for (int i = 0; i < n && rc == 0; i++) {
		double q[3];
		for (int k = 0; k < 3; k++) {
			float x = (float)c[5 * i + k];
			x = isnan(x) ? 0 : x < 0 ? 0 : x > 1 ? 1 : x;
			q[k] = (double)(unsigned short)(x * 65535.0f) / 65535.0f;
		}
		v[i] = floor((0.297 * q[0] + 0.589 * q[1] + 0.114 * q[2]) * 65535.0);
	}
	free(c);
	return rc;
}

/* The function's heights: a 16-bit grey image of it, bottom row first. The
 * function may call pattern and pigment functions, or be one
 * (function W, H { pigment { ... } }, whose colour image gives its grey):
 * those run on the device (eval_options.pattern_at). */
static int function_heights(struct eval *e, const ast_node *fn, double **h, int *w, int *hh)
{
	const ast_node *size = fn->n_kids > 2 ? fn->kids[2] : NULL;
	double sw = size ? size->kids[0]->num : 0, sh = size ? size->kids[1]->num : 0;
	*w = (int)(sw + 0.5);
	*hh = (int)(sh + 0.5);
	if (!size || *w < 2 || *hh < 2 || (double)*w * *hh > MAX_TEXELS) {
		eval_error(e, fn->loc, "a height_field's function needs a size of 2 x 2 to 4096 x 4096 points "
		           "(function W, H { ... })");
		return -1;
	}
	int f = -1, rc;
	scene_material pm;
	if (eval_function_pattern_body(fn) && e->opt->pattern_at) {
		if (eval_function_pigment(e, fn, &pm))
			return -1;
		if (pm.pattern >= 0 && scene_pigment_levels(e->s, pm.pattern) >= SCENE_FUNCTION_LEVELS_MAX) {
			static const char msg[] = "this height_field's pigment runs function patterns nested deeper than "
			                          "eclat's kernels run";
			if (!e->opt->skip_unsupported) {
				eval_error(e, fn->loc, "%s", msg);
				return -1;
			}
			eval_warn_once(e, fn->loc, msg, "%s; the height_field is left out", msg);
			return 1;
		}
	} else if ((rc = e->opt->pattern_at ? eval_function_pattern_index(e, fn, "the height_field is left out", &f)
	                                    : eval_function_index(e, fn, "the height_field is left out", &f)) != 0) {
		return rc;
	}
	if (claim_grid(e, fn->loc, *w, *hh))
		return -1;
	size_t total = (size_t)*w * *hh;
	*h = eval_xrealloc(NULL, total * sizeof **h);
	double *a = eval_xrealloc(NULL, HF_BLOCK * 3 * sizeof *a), v[HF_BLOCK];
	for (size_t at = 0; at < total; at += HF_BLOCK) {
		int n = total - at < HF_BLOCK ? (int)(total - at) : HF_BLOCK;
		for (int i = 0; i < n; i++) {
			size_t k = at + i;
			int row = (int)(k / *w), x = (int)(k % *w);
			a[3 * i] = (double)x / (*w - 1);
			a[3 * i + 1] = (double)row / (*hh - 1);
			a[3 * i + 2] = 0;
		}
		if (hf_block(e, fn, f, &pm, n, a, v)) {
			free(a);
			free(*h);
			*h = NULL;
			return -1;
		}
		for (int i = 0; i < n; i++) {
			size_t k = at + i;
			int row = (int)(k / *w), x = (int)(k % *w);
			(*h)[(size_t)(*hh - 1 - row) * *w + x] = v[i];
		}
	}
	free(a);
	return 0;
}

static void add_normal(const double *h, int w, int hh, int x0, int z0, int x1, int z1, int x2, int z2, double n[3])
{
	if (x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 || x0 >= w || x1 >= w || x2 >= w || z0 >= hh ||
	    z1 >= hh || z2 >= hh)
		return;
	double v0[3] = { x0, h[(size_t)z0 * w + x0], z0 }, t0[3], t1[3], c[3];
	for (int k = 0; k < 3; k++) {
		double v1 = k == 0 ? x1 : k == 1 ? h[(size_t)z1 * w + x1] : z1;
		double v2 = k == 0 ? x2 : k == 1 ? h[(size_t)z2 * w + x2] : z2;
		t0[k] = v2 - v0[k];
		t1[k] = v1 - v0[k];
	}
	c[0] = t0[1] * t1[2] - t0[2] * t1[1];
	c[1] = t0[2] * t1[0] - t0[0] * t1[2];
	c[2] = t0[0] * t1[1] - t0[1] * t1[0];
	double l = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
	if (!(l > 0))
		return;
	double s = c[1] < 0 ? -1 / l : 1 / l;
	for (int k = 0; k < 3; k++)
		n[k] += c[k] * s;
}

/* The grid as a mesh over [0, 1]^3. */
static void make_mesh(const double *h, int w, int hh, bool smooth, double water, scene_mesh *m)
{
	m->n_v = w * hh;
	m->v = eval_xrealloc(NULL, (size_t)m->n_v * sizeof *m->v);
	for (int z = 0; z < hh; z++)
		for (int x = 0; x < w; x++) {
			double *v = m->v[(size_t)z * w + x];
			v[0] = (double)x / (w - 1);
			v[1] = h[(size_t)z * w + x] / 65536.0;
			v[2] = (double)z / (hh - 1);
		}
	if (smooth) {   /* in the raw grid, then to [0, 1]^3 by the scale's inverse transpose */
		m->n_nrm = m->n_v;
		m->nrm = eval_xrealloc(NULL, (size_t)m->n_nrm * sizeof *m->nrm);
		for (int z = 0; z < hh; z++)
			for (int x = 0; x < w; x++) {
				double n[3] = { 0, 0, 0 };
				add_normal(h, w, hh, x, z, x + 1, z, x, z + 1, n);
				add_normal(h, w, hh, x, z, x, z + 1, x - 1, z, n);
				add_normal(h, w, hh, x, z, x - 1, z, x, z - 1, n);
				add_normal(h, w, hh, x, z, x, z - 1, x + 1, z, n);
				double *o = m->nrm[(size_t)z * w + x];
				o[0] = n[0] * (w - 1);
				o[1] = n[1] * 65536.0;
				o[2] = n[2] * (hh - 1);
			}
	}
	size_t cap = 2 * (size_t)(w - 1) * (hh - 1);
	m->face = eval_xrealloc(NULL, cap * sizeof *m->face);
	if (smooth)   /* a corner's normal is its vertex's: lowering blends them only with face_nrm */
		m->face_nrm = eval_xrealloc(NULL, cap * sizeof *m->face_nrm);
	m->n_faces = 0;
	double below = water * 65536.0;
	for (int z = 0; z + 1 < hh; z++)
		for (int x = 0; x + 1 < w; x++) {
			int p1 = z * w + x, p2 = p1 + 1, p3 = p1 + w, p4 = p3 + 1;
			int tri[2][3] = { { p1, p3, p2 }, { p2, p3, p4 } };   /* wound so that up is out */
			for (int t = 0; t < 2; t++) {
				if (water > 0 && h[tri[t][0]] < below && h[tri[t][1]] < below && h[tri[t][2]] < below)
					continue;
				if (smooth)
					memcpy(m->face_nrm[m->n_faces], tri[t], sizeof tri[t]);
				memcpy(m->face[m->n_faces++], tri[t], sizeof tri[t]);
			}
		}
}

int eval_height_field_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int err = 0, rc = 0, w = 0, hh = 0;
	double *h = NULL, water = 0;
	bool smooth = false;
	const ast_node *item = eval_next(c, &err), *name = NULL;
	if (item && item->kind == AST_FUNCTION) {
		rc = function_heights(e, item, &h, &w, &hh);
	} else {
		const ast_node *neg = NULL;
		const char *t = item ? eval_word_item(item, &neg) : NULL;
		t = neg ? NULL : t;
		bool typed = false;
		for (size_t i = 0; t && i < sizeof types / sizeof *types; i++)
			typed |= strcmp(t, types[i]) == 0;
		name = typed ? eval_next_expr(c, &err) : item;
		char *file = NULL;
		if (name && name->kind == AST_IDENT && !eval_lookup(e, name->str)) {   /* smooth, water_level... */
			eval_error(e, name->loc, "a height_field starts with its image file or its function");
			return -1;
		}
		if (!name || eval_expect_string(e, name, &file)) {
			if (!name && !err)
				eval_error(e, b->loc, "a height_field starts with its image file or its function");
			return -1;
		}
		rc = image_heights(e, name, file, typed && strcmp(t, AST_WORD_POT) == 0, &h, &w, &hh);
		free(file);
	}
	if (rc < 0)
		return -1;
	bool skipped = rc > 0;   /* --skip-unsupported: its items are still read, then it is left out */
	rc = 0;
	while (rc == 0 && (item = eval_next(c, &err)) != NULL) {
		const ast_node *neg;
		const char *wd = eval_word_item(item, &neg);
		if (wd && strcmp(wd, AST_WORD_SMOOTH) == 0 && !neg) {
			smooth = true;
		} else if (wd && strcmp(wd, AST_WORD_WATER_LEVEL) == 0) {
			rc = eval_word_float(e, c, item, neg, &water);
		} else if (wd && (strcmp(wd, AST_WORD_HIERARCHY) == 0 || strcmp(wd, AST_WORD_GAMMA) == 0 ||
		                  strcmp(wd, AST_WORD_PREMULTIPLIED) == 0) && !neg) {
			const ast_node *v = eval_next_optional(c, &err);   /* no change to the heights eclat reads */
			double f;
			if (v && eval_expect_float(e, v, &f))
				rc = -1;
		} else {
			eval_unget(c, item);   /* the object modifiers */
			break;
		}
	}
	if (rc == 0 && !err && skipped) {
		o->mesh = -1;
	} else if (rc == 0 && !err && h && w >= 2 && hh >= 2 && smooth &&
	           eval_memory_claim(e, b->loc, (double)w * hh * SMOOTH_BYTES_PER_POINT, "a smooth height field's normals")) {
		rc = -1;
	} else if (rc == 0 && !err && h && w >= 2 && hh >= 2) {
		scene_mesh m = { .loc = b->loc };
		make_mesh(h, w, hh, smooth, water, &m);
		o->mesh = scene_add_mesh(e->s, &m);
	} else if (rc == 0 && !err && h) {
		eval_error(e, b->loc, "a height_field's image needs at least 2 x 2 pixels, not %d x %d", w, hh);
		rc = -1;
	}
	free(h);
	return rc || err ? -1 : 0;
}
