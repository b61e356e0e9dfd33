/* shape.c: the table of shapes (shape.h) and what their files share. */
#include <math.h>
#include <string.h>

#include "shape.h"

#define SHAPE_CLASS_ROW(NAME, name) [SHAPE_##NAME] = &shape_##name,
static const shape_class *const classes[SHAPE_KINDS] = { SCENE_SHAPES(SHAPE_CLASS_ROW) };

const shape_class *shape_of(const scene_object *o)
{
	return classes[o->shape];
}

const shape_class *shape_named(const char *name, scene_shape *kind)
{
	for (int i = 0; i < SHAPE_KINDS; i++)
		if (strcmp(classes[i]->name, name) == 0) {
			if (kind)
				*kind = (scene_shape)i;
			return classes[i];
		}
	return NULL;
}

void shape_grow_box(double lo[3], double hi[3], const double p[3])
{
	for (int k = 0; k < 3; k++) {
		lo[k] = fmin(lo[k], p[k]);
		hi[k] = fmax(hi[k], p[k]);
	}
}

void shape_grow_xformed_box(const xform *xf, const double a[3], const double b[3], double lo[3], double hi[3])
{
	for (int c = 0; c < 8; c++) {
		double p[3] = { c & 1 ? b[0] : a[0], c & 2 ? b[1] : a[1], c & 4 ? b[2] : a[2] }, w[3];
		scene_xform_point(xf, p, w);
		shape_grow_box(lo, hi, w);
	}
}

void shape_frame(const double n[3], double u[3], double v[3])
{
	/* Duff et al., "Building an orthonormal basis, revisited" (JCGT 2017) */
	double s = n[2] >= 0 ? 1 : -1, a = -1 / (s + n[2]), b = n[0] * n[1] * a;
	u[0] = 1 + s * n[0] * n[0] * a;
	u[1] = s * b;
	u[2] = -s * n[0];
	v[0] = b;
	v[1] = s + n[1] * n[1] * a;
	v[2] = -n[1];
}

xform shape_coordinate_xform(const double origin[3], const double up[3], double radius, double length)
{
	double k[3], c, s;
	if (fabs(up[2]) > 1 - 1e-10) {   /* along z: a turn about x, by 0 or 180 degrees */
		k[0] = 1, k[1] = 0, k[2] = 0;
		c = up[2] < 0 ? -1 : 1;
		s = 0;
	} else {
		double len = sqrt(up[0] * up[0] + up[1] * up[1]);
		k[0] = -up[1] / len, k[1] = up[0] / len, k[2] = 0;
		c = up[2];
		s = sin(acos(up[2]));
	}
	/* Rodrigues' rotation by the angle whose cosine is c about k, then the scale */
	double r[3][3] = {
		{ c + (1 - c) * k[0] * k[0], (1 - c) * k[0] * k[1] - s * k[2], (1 - c) * k[0] * k[2] + s * k[1] },
		{ (1 - c) * k[1] * k[0] + s * k[2], c + (1 - c) * k[1] * k[1], (1 - c) * k[1] * k[2] - s * k[0] },
		{ (1 - c) * k[2] * k[0] - s * k[1], (1 - c) * k[2] * k[1] + s * k[0], c + (1 - c) * k[2] * k[2] },
	};
	double scale[3] = { radius, radius, length };
	xform t;
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++)
			t.m[i][j] = r[i][j] * scale[j];
		t.m[i][3] = origin[i];
	}
	return t;
}

void shape_unbounded(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	(void)o;
	for (int k = 0; k < 3; k++) {
		lo[k] = -1e10;
		hi[k] = 1e10;
	}
}
