/* lower_rainbow.c: the scene's rainbows as the kernels read them
 * (dev_rainbow), each colour_map flattened among the materials' patterns. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lower.h"

static bool rainbow_in_range(const scene_rainbow *r)
{
	double v[] = { r->angle, r->width, r->distance, r->jitter };
	for (size_t i = 0; i < sizeof v / sizeof *v; i++)
		if (!(fabs(v[i]) <= LOWER_FAR))
			return false;
	return true;
}

static float4 rainbow_f4(const double v[3], double w)
{
	return (float4){ (float)v[0], (float)v[1], (float)v[2], (float)w };
}

void lower_rainbows(lower_textures *lt, const scene *s, lower_result *out)
{
	out->rainbows = malloc((s->n_rainbows ? s->n_rainbows : 1) * sizeof *out->rainbows);
	if (!out->rainbows) {   /* as lower.c: lowering cannot go on without its arrays */
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	out->n_rainbows = 0;
	for (int i = 0; i < s->n_rainbows; i++) {
		const scene_rainbow *r = &s->rainbows[i];
		if (!rainbow_in_range(r)) {
			diag_warning(r->loc, "rainbow skipped: a number passes %g, too much for the device's single "
			             "precision", LOWER_FAR);
			continue;
		}
		out->rainbows[out->n_rainbows++] = (dev_rainbow){
			.direction = rainbow_f4(r->direction, r->angle),
			.up = rainbow_f4(r->up, r->width),
			.right = rainbow_f4(r->right, r->distance),
			.jitter = (float)r->jitter,
			.arc_angle = (float)r->arc_angle,
			.falloff_angle = (float)r->falloff_angle,
			.falloff_width = (float)(r->arc_angle - r->falloff_angle),
			.pattern = lower_texture_pigment(lt, s, r->pigment),
		};
	}
	out->params.n_rainbows = out->n_rainbows;
}
