/* shape_blob.c: blob { threshold T  sphere { <C>, R, [strength] S }...
 * cylinder { <A>, <B>, R, [strength] S }...  component S, R, <C>... }, POV-Ray
 * 3.7's blob: the points where the components' fields add up to the
 * threshold, inside where they add up to more. A component's field is
 * S (1 - d^2/R^2)^2 within R of its centre (a cylinder: of its axis between
 * its ends, and of its ends beyond them) and 0 further away (blob.cpp).
 * src/eval_blob.c reads it; its components are scene.blobs[o->poly].
 *
 * Along a ray, each piece of a component (a sphere, or a cylinder's body and
 * its two caps) is a quartic in t over the stretch where the ray is within R
 * of it. trace() walks the ray from stretch boundary to stretch boundary,
 * adds up the quartics of the pieces over each stretch and takes the first
 * root of the sum less the threshold (src/roots.c), as POV-Ray does;
 * kernels/shape_blob.cl does the same, which the device is held to
 * (tests/test_shapes.c). */
#include <math.h>

#include "ast.h"
#include "lower.h"
#include "roots.h"
#include "shape.h"
#include "vec3.h"

/* A piece along the ray: its stretch (t0, t1), where d^2 = A t^2 + B t + C. */
struct piece {
	double t0, t1, A, B, C, r2, s;
};

/* Piece k (0: the sphere or the cap at a; 1: the body; 2: the cap at b) of
 * component p along the ray; false when the ray is nowhere within reach. */
static bool piece_of(const scene_blob_part *p, int k, const double ro[3], const double rd[3], struct piece *out)
{
	double o[3], d[3];   /* the ray in the component's own space */
	if (p->xformed) {
		scene_xform_point(&p->inv, ro, o);
		scene_xform_vector(&p->inv, rd, d);
	} else {
		for (int i = 0; i < 3; i++)
			o[i] = ro[i], d[i] = rd[i];
	}
	double ax[3] = { p->b[0] - p->a[0], p->b[1] - p->a[1], p->b[2] - p->a[2] }, len = sqrt(vec3_dot(ax, ax));
	bool sphere = !(len > 0);
	if (sphere && k > 0)
		return false;
	const double *c = k == 2 ? p->b : p->a;
	double w[3] = { o[0] - c[0], o[1] - c[1], o[2] - c[2] }, dd[3] = { d[0], d[1], d[2] };
	double s0 = 0, ds = 0;
	if (!sphere) {
		for (int i = 0; i < 3; i++)
			ax[i] /= len;
		double wa[3] = { o[0] - p->a[0], o[1] - p->a[1], o[2] - p->a[2] };
		s0 = vec3_dot(wa, ax);
		ds = vec3_dot(d, ax);
		if (k == 1) {   /* the body: the distance to the axis */
			double ws = vec3_dot(w, ax);
			for (int i = 0; i < 3; i++) {
				w[i] -= ws * ax[i];
				dd[i] -= ds * ax[i];
			}
		}
	}
	double A = vec3_dot(dd, dd), B = 2 * vec3_dot(dd, w), C = vec3_dot(w, w), r2 = p->r * p->r;
	double t0 = -INFINITY, t1 = INFINITY;
	if (A > 0) {
		double disc = B * B - 4 * A * (C - r2);
		if (!(disc > 0))
			return false;
		double q = sqrt(disc);
		t0 = (-B - q) / (2 * A);
		t1 = (-B + q) / (2 * A);
	} else if (!(C < r2)) {
		return false;
	}
	if (!sphere) {   /* the part of the axis this piece holds: s < 0, 0..len, > len */
		double lo = k == 0 ? -INFINITY : k == 1 ? 0 : len, hi = k == 0 ? 0 : k == 1 ? len : INFINITY;
		if (ds != 0) {
			double ta = (lo - s0) / ds, tb = (hi - s0) / ds;
			t0 = fmax(t0, fmin(ta, tb));
			t1 = fmin(t1, fmax(ta, tb));
		} else if (!(s0 >= lo && s0 <= hi)) {
			return false;
		}
	}
	if (!(t0 < t1))
		return false;
	*out = (struct piece){ t0, t1, A, B, C, r2, p->s };
	return true;
}

/* The nearest t in (tmin, tmax] where the fields reach the threshold, or INFINITY. */
static double blob_hit(const scene_blob *bl, const double o[3], const double d[3], double tmin, double tmax)
{
	double cur = -INFINITY;
	for (;;) {
		double next = INFINITY;
		struct piece pc;
		for (int j = 0; j < bl->n_parts; j++)
			for (int k = 0; k < 3; k++)
				if (piece_of(&bl->part[j], k, o, d, &pc)) {
					if (pc.t0 > cur && pc.t0 < next)
						next = pc.t0;
					if (pc.t1 > cur && pc.t1 < next)
						next = pc.t1;
				}
		if (next == INFINITY || cur >= tmax)
			return INFINITY;
		if (cur > -INFINITY && next > tmin) {   /* the stretch (cur, next): its pieces' quartics */
			double mid = 0.5 * (cur + next), c[5] = { -bl->threshold, 0, 0, 0, 0 };
			bool any = false;
			for (int j = 0; j < bl->n_parts; j++)
				for (int k = 0; k < 3; k++)
					if (piece_of(&bl->part[j], k, o, d, &pc) && pc.t0 < mid && mid < pc.t1) {
						double s = pc.s, r2 = pc.r2, r4 = r2 * r2;
						c[0] += s * (1 - 2 * pc.C / r2 + pc.C * pc.C / r4);
						c[1] += s * (-2 * pc.B / r2 + 2 * pc.B * pc.C / r4);
						c[2] += s * (-2 * pc.A / r2 + (pc.B * pc.B + 2 * pc.A * pc.C) / r4);
						c[3] += s * 2 * pc.A * pc.B / r4;
						c[4] += s * pc.A * pc.A / r4;
						any = true;
					}
			double root;
			if (any && roots_find(c, 4, fmax(cur, tmin), fmin(next, tmax), &root, 1) == 1)
				return root;
		}
		cur = next;
	}
}

/* Component p's field at x (the blob's space), its gradient added to g. */
static double part_field(const scene_blob_part *p, const double bx[3], double g[3])
{
	double x[3] = { bx[0], bx[1], bx[2] };
	if (p->xformed)
		scene_xform_point(&p->inv, bx, x);
	double ax[3] = { p->b[0] - p->a[0], p->b[1] - p->a[1], p->b[2] - p->a[2] }, len = sqrt(vec3_dot(ax, ax));
	double v[3] = { x[0] - p->a[0], x[1] - p->a[1], x[2] - p->a[2] };
	if (len > 0) {   /* from the nearest point of the axis */
		double s = vec3_dot(v, ax) / (len * len);
		s = s < 0 ? 0 : s > 1 ? 1 : s;
		for (int i = 0; i < 3; i++)
			v[i] -= s * ax[i];
	}
	double r2 = p->r * p->r, d2 = vec3_dot(v, v);
	if (d2 >= r2)
		return 0;
	double u = 1 - d2 / r2, gl[3];
	for (int i = 0; i < 3; i++)
		gl[i] = p->s * 2 * u * (-2 * v[i] / r2);
	for (int i = 0; i < 3; i++)   /* back to the blob's space: the transpose of inv */
		g[i] += p->xformed ? p->inv.m[0][i] * gl[0] + p->inv.m[1][i] * gl[1] + p->inv.m[2][i] * gl[2] : gl[i];
	return p->s * u * u;
}

/* The field at x and its gradient into g. */
static double field(const scene_blob *bl, const double x[3], double g[3])
{
	double f = 0;
	g[0] = g[1] = g[2] = 0;
	for (int j = 0; j < bl->n_parts; j++)
		f += part_field(&bl->part[j], x, g);
	return f;
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	const scene_blob *bl = &s->blobs[o->poly];
	double t = blob_hit(bl, ro, rd, tmin, h->t);
	if (!(t < h->t))
		return;
	double x[3] = { ro[0] + t * rd[0], ro[1] + t * rd[1], ro[2] + t * rd[2] }, g[3];
	field(bl, x, g);
	h->t = t;
	for (int i = 0; i < 3; i++)   /* the field falls outward */
		h->n[i] = -g[i];
	if (h->n[0] == 0 && h->n[1] == 0 && h->n[2] == 0)
		h->n[1] = 1;
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	double g[3];
	return field(&s->blobs[o->poly], p, g) > s->blobs[o->poly].threshold;
}

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	const scene_blob *bl = &s->blobs[o->poly];
	for (int j = 0; j < bl->n_parts; j++) {
		const scene_blob_part *p = &bl->part[j];
		double a[3], b[3];
		for (int i = 0; i < 3; i++) {
			a[i] = fmin(p->a[i], p->b[i]) - p->r;
			b[i] = fmax(p->a[i], p->b[i]) + p->r;
		}
		/* from the component's own space, through the blob's, to world */
		xform to_world = p->xformed ? scene_xform_then(&p->xf, &o->xf) : o->xf;
		shape_grow_xformed_box(&to_world, a, b, lo, hi);
	}
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	const scene_blob *bl = &s->blobs[o->poly];
	if (bl->n_parts == 0)
		return 0;
	dev_prim p = { .type = PRIM_BLOB };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "blob with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	for (int j = 0; j < bl->n_parts; j++)
		if (bl->part[j].texture) {   /* POV-Ray's blob of several textures */
			lower_blob_textures(lw, o, mat);
			break;
		}
	p.link = lower_add_data(lw, (float4){ (float)bl->n_parts, (float)bl->threshold, 0, 0 });
	for (int j = 0; j < bl->n_parts; j++) {   /* two records a component: kernels/shape_blob.cl */
		const scene_blob_part *c = &bl->part[j];
		const xform *m = &c->inv;
		float4 rows[3] = { { 0 } };
		for (int i = 0; i < 3 && c->xformed; i++)
			rows[i] = (float4){ (float)m->m[i][0], (float)m->m[i][1], (float)m->m[i][2], (float)m->m[i][3] };
		lower_add_record(lw, (float4){ (float)c->a[0], (float)c->a[1], (float)c->a[2], (float)c->r },
		                 (float4){ (float)c->b[0], (float)c->b[1], (float)c->b[2], (float)c->s },
		                 (float4){ c->xformed ? 1.0f : 0.0f, 0, 0, 0 });
		lower_add_record(lw, rows[0], rows[1], rows[2]);
	}
	double blo[3] = { INFINITY, INFINITY, INFINITY }, bhi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, blo, bhi);
	lower_add_prim(lw, p, mat, id, blo, bhi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "blob %d", o->poly);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_blob = {
	.name = AST_WORD_BLOB, .args = NULL, .needs = "components", .flags = SHAPE_STURM,
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
