/* shape_triangle.c: triangle { <A>, <B>, <C> } and
 * smooth_triangle { <A>, <NA>, <B>, <NB>, <C>, <NC> }, baked into world space
 * (kernels/shape_triangle.cl). A triangle has no inside. */
#include <math.h>
#include <string.h>

#include "lower.h"
#include "shape.h"
#include "vec3.h"

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	double w[3];
	for (int i = 0; i < 3; i++) {
		scene_xform_point(&o->xf, o->p[i], w);
		shape_grow_box(lo, hi, w);
	}
}

/* Moeller-Trumbore; the normal is the flat one, or the corners' normals (nrm,
 * NULL for none) weighted by the barycentric coordinates, turned to face the
 * ray as POV-Ray turns a triangle's (a triangle has no inside). The sign of
 * n . d is the same in object and world space. Shared with shape_mesh.c. */
void shape_trace_triangle(const double *a, const double *b, const double *c, const double *const *nrm,
                          const double o[3], const double d[3], double tmin, shape_hit *h)
{
	double e1[3], e2[3], p[3], q[3], s[3];
	for (int i = 0; i < 3; i++) {
		e1[i] = b[i] - a[i];
		e2[i] = c[i] - a[i];
		s[i] = o[i] - a[i];
	}
	vec3_cross(d, e2, p);
	double det = vec3_dot(e1, p);
	if (fabs(det) < 1e-300)
		return;
	double u = vec3_dot(s, p) / det;
	vec3_cross(s, e1, q);
	double v = vec3_dot(d, q) / det, t = vec3_dot(e2, q) / det;
	if (u < 0 || v < 0 || u + v > 1 || !(t > tmin && t < h->t))
		return;
	double n[3];
	if (nrm && nrm[0])
		for (int i = 0; i < 3; i++)
			n[i] = (1 - u - v) * nrm[0][i] + u * nrm[1][i] + v * nrm[2][i];
	else
		vec3_cross(e1, e2, n);
	if (vec3_dot(n, d) > 0)
		for (int i = 0; i < 3; i++)
			n[i] = -n[i];
	h->t = t;
	memcpy(h->n, n, sizeof h->n);
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	const double *nrm[3] = { o->n[0], o->n[1], o->n[2] };
	shape_trace_triangle(o->p[0], o->p[1], o->p[2], o->shape == SHAPE_SMOOTH_TRIANGLE ? nrm : NULL, ro, rd, tmin,
	                     h);
}

static int lower_flat(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	(void)s;
	double v[3][3];
	for (int i = 0; i < 3; i++)
		scene_xform_point(&o->xf, o->p[i], v[i]);
	lower_add_triangle(lw, v, NULL, mat, id, o->loc);
	return 0;
}

/* Its corners and normals in world space: normals map by the transposed inverse. */
static int lower_smooth(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	(void)s;
	xform inv;
	double v[3][3], n[3][3];
	if (lower_invert(&o->xf, &inv)) {
		diag_warning(o->loc, "smooth_triangle with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	for (int i = 0; i < 3; i++) {
		scene_xform_point(&o->xf, o->p[i], v[i]);
		for (int k = 0; k < 3; k++)
			n[i][k] = inv.m[0][k] * o->n[i][0] + inv.m[1][k] * o->n[i][1] + inv.m[2][k] * o->n[i][2];
	}
	lower_add_triangle(lw, v, (const double (*)[3])n, mat, id, o->loc);
	return 0;
}

static void dump_flat(FILE *out, const scene_object *o)
{
	fputs("triangle", out);
	for (int i = 0; i < 3; i++) {
		double w[3];
		scene_xform_point(&o->xf, o->p[i], w);
		scene_dump_vec(out, "", w);
	}
}

/* A normal's image: the inverse transpose of the transform, normalized, its
 * sign kept for a mirroring transform. */
static void xform_normal(const xform *t, const double n[3], double out[3])
{
	const double (*m)[4] = t->m;
	double c[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			int a = (i + 1) % 3, b = (i + 2) % 3, p = (j + 1) % 3, q = (j + 2) % 3;
			c[i][j] = m[a][p] * m[b][q] - m[a][q] * m[b][p];   /* cofactors: the inverse transpose times det */
		}
	double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2], r[3], l = 0;
	for (int i = 0; i < 3; i++) {
		r[i] = c[i][0] * n[0] + c[i][1] * n[1] + c[i][2] * n[2];
		l += r[i] * r[i];
	}
	l = det < 0 ? -sqrt(l) : sqrt(l);
	for (int i = 0; i < 3; i++)
		out[i] = l > 0 ? r[i] / l : 0;
}

static void dump_smooth(FILE *out, const scene_object *o)
{
	double w[3];
	fputs("smooth_triangle", out);
	for (int i = 0; i < 3; i++) {
		scene_xform_point(&o->xf, o->p[i], w);
		scene_dump_vec(out, "", w);
		xform_normal(&o->xf, o->n[i], w);
		scene_dump_vec(out, "normal", w);
	}
}

const shape_class shape_triangle = {
	.name = "triangle", .args = "vvv", .needs = "three corners",
	.bounds = bounds, .trace = trace, .lower = lower_flat, .dump = dump_flat,
};

const shape_class shape_smooth_triangle = {
	.name = "smooth_triangle", .args = "vnvnvn", .needs = "three corners, each with a normal",
	.bounds = bounds, .trace = trace, .lower = lower_smooth, .dump = dump_smooth,
};
