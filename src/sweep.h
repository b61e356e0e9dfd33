/* sweep.h: a sphere_sweep's segments (src/shape_sphere_sweep.c), which its
 * reader (src/eval_sweep.c), its class and the device's records share. */
#ifndef ECLAT_SWEEP_H
#define ECLAT_SWEEP_H

#include "scene.h"

/* The splines, a sphere_sweep's param[0]: POV-Ray's linear_spline,
 * cubic_spline (Catmull-Rom) and b_spline. */
enum { SWEEP_LINEAR, SWEEP_CUBIC, SWEEP_B_SPLINE };

/* A segment: its centre and radius, c[k] the coefficients of u^k (x, y, z,
 * radius; those past order are 0), and a box that holds it. */
typedef struct {
	double c[4][4];
	int order;
	double lo[3], hi[3];
} sweep_seg;

/* How many segments o's spheres make (count - 1 linear, count - 3 cubic). */
int sweep_segments(const scene *s, const scene_object *o);
void sweep_segment(const scene *s, const scene_object *o, int i, sweep_seg *g);
/* The nearest t in (tmin, tmax) where the ray o + t d meets the sweep's
 * surface, else tmax. */
double sweep_hit(const sweep_seg *segs, int n, const double o[3], const double d[3], double tmin, double tmax);

#endif
