/* lower_fog.c: the scene's fogs as the kernels read them (dev_fog), and how
 * many solid objects hold the camera, which POV-Ray's fog needs: a ray inside
 * a solid (non-hollow) object is not fogged, and POV-Ray finds the objects
 * around the camera before it traces (TracePixel::InitRayContainerState). */
#include <math.h>
#include <stdlib.h>

#include "lower.h"
#include "shape.h"
#include "csg.h"

static float4 fog_f4(const double v[3], double w)
{
	return (float4){ (float)v[0], (float)v[1], (float)v[2], (float)w };
}

static dev_fog lower_fog(const scene_fog *f)
{
	return (dev_fog){
		.colour = { f->colour[0], f->colour[1], f->colour[2], f->colour[3] },
		.up = fog_f4(f->up, f->colour[4]),
		.turb = fog_f4(f->turbulence, f->turb_depth),
		.distance = (float)f->distance,
		.offset = (float)f->offset,
		.alt = (float)f->alt,
		.omega = (float)f->omega,
		.lambda = (float)f->lambda,
		.octaves = f->octaves,
		.type = f->type == SCENE_FOG_GROUND ? FOG_GROUND : FOG_CONSTANT,
		.turb_on = f->has_turb,
	};
}

static bool fog_in_range(const scene_fog *f)
{
	double v[] = { f->distance, f->offset, f->alt, f->omega, f->lambda, f->turb_depth, f->turbulence[0],
	               f->turbulence[1], f->turbulence[2], f->colour[0], f->colour[1], f->colour[2] };
	for (size_t i = 0; i < sizeof v / sizeof *v; i++)
		if (!(fabs(v[i]) <= LOWER_FAR))
			return false;
	return true;
}

int lower_fogs(const scene *s, lower_result *out)
{
	out->fogs = malloc((s->n_fogs ? s->n_fogs : 1) * sizeof *out->fogs);
	if (!out->fogs)
		return -1;
	out->n_fogs = 0;
	for (int i = 0; i < s->n_fogs; i++) {
		if (fog_in_range(&s->fogs[i]))
			out->fogs[out->n_fogs++] = lower_fog(&s->fogs[i]);
		else
			diag_warning(s->fogs[i].loc, "fog skipped: a number passes %g, too much for the device's "
			             "single precision", LOWER_FAR);
	}
	return 0;
}

/* Whether world point x is inside scene object o (its class's inside test in
 * object space); a shape without one (a triangle, a mesh without inside_vector) holds nothing. */
static bool object_inside(const scene *s, const scene_object *o, const double x[3])
{
	xform inv;
	double p[3];
	if (!shape_of(o)->inside || lower_invert(&o->xf, &inv))
		return false;
	scene_xform_point(&inv, x, p);
	return shape_of(o)->inside(s, o, p);
}

struct leaves {
	const scene *s;
	const scene_object *leaf;
	const double *x;
};

static bool leaf_inside(void *ctx, int k)
{
	const struct leaves *c = ctx;
	return object_inside(c->s, &c->leaf[k], c->x);
}

int lower_camera_solids(const scene *s)
{
	const double *x = s->camera.location;
	int n = 0;
	for (int i = 0; i < s->n_objects;) {
		const scene_object *o = &s->objects[i];
		int g = o->csg - 1;
		if (o->pattern) {   /* an object pattern's: no surface a ray passes through */
			i++;
			continue;
		}
		if (g >= 0 && g < s->n_csgs && s->csgs[g].first == i) {
			const scene_csg *c = &s->csgs[g];
			struct leaves l = { s, o, x };
			n += !(o->flags & OBJ_HOLLOW) && csg_inside(c->ops, c->n_ops, leaf_inside, &l);
			i += c->n_leaves;
			continue;
		}
		n += !(o->flags & OBJ_HOLLOW) && !o->clip && object_inside(s, o, x);
		i++;
	}
	return n;
}
