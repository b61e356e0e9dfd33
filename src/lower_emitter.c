/* lower_emitter.c: the table by which the path tracer picks an emissive
 * primitive for next-event estimation.
 *
 *   lower_emitters(out);   after the primitives are joined (their links final)
 *
 * Every emitting primitive of the top level whose shape can be sampled
 * (PRIM_EMITTERS in kernels/shared.h: triangles, spheres, discs, cylinders;
 * a box that emits is lowered as its twelve triangles) gets a row, chosen
 * with probability proportional to its power: its area in world space times
 * the luminance of its emission (its average pigment's). The primitive finds
 * its row as kernels/shape.cl's shape_emitter says: in its link, or in its
 * first record's. Planes are unbounded, and other shapes, meshes' triangles
 * and CSG's leaves have no sampler: rays alone find them. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lower.h"
#include "vec3.h"

/* The rows of a shape's map from world space (kernels/intersect.cl), and
 * |det| of their 3 x 3 part. */
static double rows_of(const dev_prim *p, double m[3][3])
{
	const float4 *r[3] = { &p->a, &p->b, &p->c };
	for (int i = 0; i < 3; i++) {
		m[i][0] = r[i]->x;
		m[i][1] = r[i]->y;
		m[i][2] = r[i]->z;
	}
	double bc[3];
	vec3_cross(m[1], m[2], bc);
	return fabs(vec3_dot(m[0], bc));
}

/* The world area element over the shape's own, on a surface of unit normal n
 * there: |M^T n| / |det M|, as intersect_area_scale. */
static double area_scale(double m[3][3], double det, const double n[3])
{
	double v[3];
	for (int k = 0; k < 3; k++)
		v[k] = n[0] * m[0][k] + n[1] * m[1][k] + n[2] * m[2][k];
	return sqrt(vec3_dot(v, v)) / det;
}

static double triangle_area(const dev_prim *p)
{
	double e1[3] = { p->b.x - p->a.x, p->b.y - p->a.y, p->b.z - p->a.z };
	double e2[3] = { p->c.x - p->a.x, p->c.y - p->a.y, p->c.z - p->a.z }, c[3];
	vec3_cross(e1, e2, c);
	return 0.5 * sqrt(vec3_dot(c, c));
}

/* A disc's ring, pi (1 - hole^2) in its own space (kernels/shape_disc.cl). */
static double disc_area(const lower_result *r, const dev_prim *p)
{
	double m[3][3], det = rows_of(p, m), nz[3] = { 0, 0, 1 };
	return M_PI * (1 - r->prims[p->link].a.x) * area_scale(m, det, nz);
}

/* A cylinder's side (its own space's x^2 + y^2 = 1, 0 <= z <= 1), whose area
 * scale changes around it when the cylinder is scaled across its axis: the
 * integral by the midpoint rule, which for a smooth periodic integrand is
 * exact far beyond single precision at this count. */
static double cylinder_side_area(double m[3][3], double det)
{
	enum { STEPS = 256 };
	double sum = 0;
	for (int i = 0; i < STEPS; i++) {
		double phi = 2 * M_PI * (i + 0.5) / STEPS, n[3] = { cos(phi), sin(phi), 0 };
		sum += area_scale(m, det, n);
	}
	return 2 * M_PI * sum / STEPS;
}

/* A cylinder's area; its record's a.z becomes the side's share of it, the
 * probability with which kernels/shape_cone.cl's sampler picks the side. */
static double cylinder_area(lower_result *r, const dev_prim *p)
{
	double m[3][3], det = rows_of(p, m), nz[3] = { 0, 0, 1 };
	double side = cylinder_side_area(m, det);
	double ends = r->prims[p->link].a.y != 0 ? 2 * M_PI * area_scale(m, det, nz) : 0;
	r->prims[p->link].a.z = (float)(side / (side + ends));
	return side + ends;
}

/* The primitive's area in world space; 0 for a shape that has no sampler. */
static double emitter_area(lower_result *r, const dev_prim *p)
{
	switch (p->type) {
	case PRIM_TRIANGLE: return triangle_area(p);
	case PRIM_SPHERE: return 4 * M_PI * p->a.w * p->a.w;
	case PRIM_DISC: return disc_area(r, p);
	case PRIM_CYLINDER: return cylinder_area(r, p);
	default: return 0;
	}
}

/* Where the primitive keeps its row (kernels/shape.cl's shape_emitter). */
static void emitter_link(lower_result *r, dev_prim *p, int row)
{
	if (p->type == PRIM_TRIANGLE || p->type == PRIM_SPHERE)
		p->link = row;
	else
		r->prims[p->link].link = row;
}

/* lower.h */
int lower_emitters(lower_result *r)
{
	double total = 0;
	r->emitters = malloc((r->n_prims ? r->n_prims : 1) * sizeof *r->emitters);
	if (!r->emitters) {
		fprintf(stderr, "eclat: out of memory for the emitters' table\n");
		return -1;
	}
	for (int i = 0; i < r->n_prims; i++) {
		dev_prim *p = &r->prims[i];
		const dev_material *m = &r->materials[p->material];   /* its average pigment */
		float4 e = { m->pigment.x * m->emission.x, m->pigment.y * m->emission.y, m->pigment.z * m->emission.z, 0 };
		double lum = 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
		if (lum <= 0)
			continue;
		double area = emitter_area(r, p);
		if (!(area > 0))
			continue;
		emitter_link(r, p, r->n_emitters);
		r->emitters[r->n_emitters++] = (dev_emitter){ .cdf = (float)(lum * area), .area = (float)area, .prim = i };
		total += lum * area;
	}
	double run = 0;
	for (int i = 0; i < r->n_emitters; i++) {
		double power = r->emitters[i].cdf;
		run += power;
		r->emitters[i].pdf = (float)(power / total);
		r->emitters[i].cdf = i == r->n_emitters - 1 ? 1.0f : (float)(run / total);
	}
	return 0;
}
