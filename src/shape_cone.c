/* shape_cone.c: cylinder { <Base>, <Cap>, Radius [open] } and
 * cone { <Base>, Base_Radius, <Cap>, Cap_Radius [open] }, as POV-Ray 3.7's
 * cone.cpp makes them: each is kept in a space of its own, the map from it to
 * object space computed as POV-Ray's Compute_Cone_Data does.
 *   cylinder: the unit cylinder x^2 + y^2 = 1, 0 <= z <= 1;
 *   cone: x^2 + y^2 = z^2, dist <= z <= 1, z = 1 the end with the larger
 *   radius (scaled to 1) and z = dist the other (radius dist there); the
 *   point of the cone, where it would end, is the origin. A cone whose radii
 *   differ by less than POV-Ray's EPSILON is a cylinder; radii of opposite
 *   signs make two cones point to point (dist < 0), as in POV-Ray.
 * Both have their end discs unless open, and an inside either way (POV-Ray's
 * Inside ignores open). On the device (kernels/shape_cone.cl) the primitive's
 * rows are the map from world space to that space (stretched along z to
 * 0 <= z <= 1 for a cone), about the shape's centre, and its PRIM_DATA
 * records hold dist and whether it is capped, then the centre. End points
 * less than EPSILON apart are an error, as in POV-Ray; a radius of 0 draws
 * nothing, as in POV-Ray, and lowering leaves such a shape out with a
 * warning. */
#include <math.h>
#include <stdbool.h>

#include "lower.h"
#include "shape.h"

#define POV_EPSILON 1e-10   /* POV-Ray's EPSILON */

/* A cylinder or cone in its own space: to_object maps it to object space. */
typedef struct {
	xform to_object;
	double dist;      /* the cone's smaller end's z (0 for a cylinder) */
	double radius;    /* its radius at z = 1 (the larger end's) */
	bool cylinder;
} cone_space;

static double distance3(const double a[3], const double b[3], double axis[3])
{
	for (int k = 0; k < 3; k++)
		axis[k] = a[k] - b[k];
	return sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
}

/* POV-Ray's Compute_Cylinder_Data: the unit cylinder from base to apex. */
static void cylinder_space(const double apex[3], const double base[3], double radius, cone_space *c)
{
	double axis[3], len = distance3(apex, base, axis);
	for (int k = 0; k < 3; k++)
		axis[k] /= len;
	c->to_object = shape_coordinate_xform(base, axis, radius, len);
	c->dist = 0;
	c->radius = radius;
	c->cylinder = true;
}

/* POV-Ray's Compute_Cone_Data, which calls POV-Ray's first point and radius the
 * apex and the second the base. -1 when the end points are one point. */
static int space(const scene_object *o, cone_space *c)
{
	const double *apex = o->p[0], *base = o->p[1];
	double axis[3], len = distance3(apex, base, axis);
	if (!(len >= POV_EPSILON))
		return -1;
	if (o->shape == SHAPE_CYLINDER) {
		cylinder_space(apex, base, o->radius, c);
		return 0;
	}
	double ra = o->radius, rb = o->param[0];
	if (fabs(ra - rb) < POV_EPSILON) {
		cylinder_space(apex, base, ra, c);
		return 0;
	}
	for (int k = 0; k < 3; k++)
		axis[k] /= len;
	if (ra < rb) {   /* the larger end at z = 1 */
		const double *p = apex;
		double r = ra;
		apex = base, base = p;
		ra = rb, rb = r;
		for (int k = 0; k < 3; k++)
			axis[k] = -axis[k];
	}
	double tmpf = rb * len / (ra - rb), tlen = tmpf + len, origin[3];
	if ((ra - rb) * len / tlen < POV_EPSILON) {   /* it looks like a cylinder */
		cylinder_space(apex, base, ra, c);
		return 0;
	}
	for (int k = 0; k < 3; k++)
		origin[k] = base[k] - axis[k] * tmpf;
	c->dist = tmpf / tlen;
	c->to_object = shape_coordinate_xform(origin, axis, ra, tlen);
	c->radius = ra;
	c->cylinder = false;
	return 0;
}

static const char *check(const scene_object *o)
{
	cone_space c;
	if (space(o, &c) == 0)
		return NULL;
	return o->shape == SHAPE_CYLINDER ? "a cylinder needs a base and a cap that are not the same point"
	                                  : "a cone needs a base and a cap that are not the same point";
}

/* POV-Ray's box, [-1, 1] x [-1, 1] x [dist, 1] in the shape's space (wider
 * where the end at dist is the larger, which POV-Ray's box cuts off). */
static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	cone_space c;
	if (space(o, &c))
		return;
	double m = fmax(1, fabs(c.dist));
	double a[3] = { -m, -m, fmin(c.dist, 1) }, b[3] = { m, m, fmax(c.dist, 1) };
	xform to_world = scene_xform_then(&c.to_object, &o->xf);
	shape_grow_xformed_box(&to_world, a, b, lo, hi);
}

/* A ray in the shape's space: its origin P, its unit direction D and the length
 * len of the given direction there (t along the given ray is d / len). -1 when
 * the shape has no such space (a radius of 0). */
static int ray_in_space(const cone_space *c, const double ro[3], const double rd[3], double P[3], double D[3],
                        double *len, xform *inv)
{
	if (lower_invert(&c->to_object, inv))
		return -1;
	scene_xform_point(inv, ro, P);
	scene_xform_vector(inv, rd, D);
	*len = sqrt(D[0] * D[0] + D[1] * D[1] + D[2] * D[2]);
	if (!(*len > 0))
		return -1;
	for (int k = 0; k < 3; k++)
		D[k] /= *len;
	return 0;
}

/* POV-Ray's Cone::Intersect in double precision: the side's roots within the
 * ends, and the end discs unless open; the nearest past tmin is kept. Each
 * hit is a distance along the unit direction and the part it is on. */
enum { SIDE_HIT, CAP_HIT, BASE_HIT };   /* the side, the end at z = 1, the end at z = dist */

static int side_roots(const cone_space *c, const double P[3], const double D[3], double roots[2])
{
	int n = 0;
	if (c->cylinder) {
		double a = D[0] * D[0] + D[1] * D[1];
		if (a > POV_EPSILON) {
			double b = P[0] * D[0] + P[1] * D[1], cc = P[0] * P[0] + P[1] * P[1] - 1, d = b * b - a * cc;
			if (d >= 0) {
				roots[n++] = (-b + sqrt(d)) / a;
				roots[n++] = (-b - sqrt(d)) / a;
			}
		}
		return n;
	}
	double a = D[0] * D[0] + D[1] * D[1] - D[2] * D[2];
	double b = D[0] * P[0] + D[1] * P[1] - D[2] * P[2];
	double cc = P[0] * P[0] + P[1] * P[1] - P[2] * P[2];
	if (fabs(a) < POV_EPSILON) {
		if (fabs(b) > POV_EPSILON)
			roots[n++] = -0.5 * cc / b;
	} else {
		double d = b * b - a * cc;
		if (d >= 0) {
			roots[n++] = (-b - sqrt(d)) / a;
			roots[n++] = (-b + sqrt(d)) / a;
		}
	}
	return n;
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	cone_space c;
	xform inv;
	double P[3], D[3], len;
	if (space(o, &c) || ray_in_space(&c, ro, rd, P, D, &len, &inv))
		return;
	double d[4];
	int part[4], n = side_roots(&c, P, D, d);
	for (int i = 0; i < n; i++)
		part[i] = SIDE_HIT;
	for (int i = n - 1; i >= 0; i--) {   /* within the ends */
		double z = P[2] + d[i] * D[2];
		if (!(z >= c.dist && z <= 1))
			d[i] = d[--n];
	}
	if (!(o->shape_flags & SHAPE_OPEN) && fabs(D[2]) > POV_EPSILON) {
		double ends[2] = { 1, c.dist }, r2[2] = { 1, c.cylinder ? 1 : c.dist * c.dist };
		for (int e = 0; e < 2; e++) {
			double de = (ends[e] - P[2]) / D[2], x = P[0] + de * D[0], y = P[1] + de * D[1];
			if (x * x + y * y <= r2[e]) {
				d[n] = de;
				part[n++] = e == 0 ? CAP_HIT : BASE_HIT;
			}
		}
	}
	int best = -1;
	for (int i = 0; i < n; i++) {   /* of equal ones, the last, as POV-Ray's trace() takes */
		double t = d[i] / len;
		if (t > tmin && t < h->t && (best < 0 || d[i] <= d[best]))
			best = i;
	}
	if (best < 0)
		return;
	/* the normal in the shape's space, as POV-Ray's Cone::Normal gives it */
	double q[3] = { P[0] + d[best] * D[0], P[1] + d[best] * D[1], P[2] + d[best] * D[2] }, nc[3] = { 0, 0, 0 };
	if (part[best] == SIDE_HIT) {
		nc[0] = q[0];
		nc[1] = q[1];
		nc[2] = c.cylinder ? 0 : -q[2];
	} else {
		nc[2] = part[best] == CAP_HIT ? 1 : -1;
	}
	h->t = d[best] / len;
	for (int i = 0; i < 3; i++)   /* to object space by the inverse's transpose */
		h->n[i] = inv.m[0][i] * nc[0] + inv.m[1][i] * nc[1] + inv.m[2][i] * nc[2];
}

/* POV-Ray's Cone::Inside: open or not, the solid; POV-Ray's EPSILON leans
 * outward for an open shape and inward for a closed one. */
static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	cone_space c;
	xform inv;
	if (space(o, &c) || lower_invert(&c.to_object, &inv))
		return false;
	double q[3];
	scene_xform_point(&inv, p, q);
	double offset = o->shape_flags & SHAPE_OPEN ? POV_EPSILON : -POV_EPSILON, w2 = q[0] * q[0] + q[1] * q[1];
	double r2 = c.cylinder ? 1 : q[2] * q[2];
	return !(w2 > r2 + offset || q[2] < c.dist - offset || q[2] > 1 + offset);
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	cone_space c;
	if (space(o, &c))
		return 0;   /* check() has said so */
	/* the device's cone space: POV-Ray's stretched along z, from dist to 1 into 0 to 1 */
	double stretch[3] = { 1, 1, 1 - c.dist }, from[3] = { 0, 0, c.dist };
	xform z = scene_xform_scale(stretch), move = scene_xform_translate(from);
	z = scene_xform_then(&z, &move);
	xform to_object = scene_xform_then(&z, &c.to_object), to_world = scene_xform_then(&to_object, &o->xf);
	dev_prim p = { .type = c.cylinder ? PRIM_CYLINDER : PRIM_CONE };
	double mid[3] = { 0, 0, 0.5 }, centre[3];
	float4 cf;
	scene_xform_point(&to_world, mid, centre);
	if (lower_local_rows_about(&to_world, centre, &p, &cf)) {
		if (c.radius == 0)
			diag_warning(o->loc, "%s of radius 0 skipped", shape_of(o)->name);
		else
			diag_warning(o->loc, "%s with a singular transform (a scale of 0?) skipped", shape_of(o)->name);
		return 0;
	}
	p.link = lower_add_data(lw, (float4){ (float)c.dist, o->shape_flags & SHAPE_OPEN ? 0.0f : 1.0f, 0, 0 });
	lower_add_data(lw, cf);   /* the next record: the centre */
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs(shape_of(o)->name, out);
	scene_dump_vec(out, "base", o->p[0]);
	if (o->shape == SHAPE_CONE) {
		fputs(" radius ", out);
		scene_dump_num(out, o->radius);
	}
	scene_dump_vec(out, "cap", o->p[1]);
	fputs(" radius ", out);
	scene_dump_num(out, o->shape == SHAPE_CONE ? o->param[0] : o->radius);
	if (o->shape_flags & SHAPE_OPEN)
		fputs(" open", out);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_cylinder = {
	.name = "cylinder", .args = "vvf", .needs = "a base, a cap and a radius", .flags = SHAPE_OPEN,
	.check = check, .bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};

const shape_class shape_cone = {
	.name = "cone", .args = "vfvf", .needs = "a base and its radius, and a cap and its radius", .flags = SHAPE_OPEN,
	.check = check, .bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
