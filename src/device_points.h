/* device_points.h: pattern and pigment functions called while a scene is read.
 *
 * POV-Ray evaluates a pattern function wherever the scene calls it, in an
 * #if, a #while or a macro that builds a height field from it (shapes.inc's
 * HF_ macros, math.inc's vGradient). eclat's one pattern evaluator is the
 * kernels' (kernels/pattern.cl): the pigment is lowered as a render lowers
 * it and a small kernel (pattern_points, kernels/raycast.cl) evaluates it at
 * the point, so a value read while parsing is the value the render sees.
 * The device and the program (no integrator in it) are opened at the first
 * call; a scene that calls no pattern function opens nothing. */
#ifndef ECLAT_DEVICE_POINTS_H
#define ECLAT_DEVICE_POINTS_H

#include "scene.h"

typedef struct device_points device_points;

/* device: --device's index (-1: the default device); kernel_dir:
 * --kernel-dir or NULL. Opens nothing yet. */
device_points *device_points_new(int device, const char *kernel_dir);

/* eval_options.pattern_at (eval.h): pigment's pattern value (colour false:
 * out[5 * i]) or colour (out[5 * i ...]: red, green, blue, filter,
 * transmit) at the n points p, in one launch. 0, or -1 after an error at loc
 * (no device, a kernel that fails). */
int device_points_eval(void *self, const scene *s, int pigment, bool colour, int n, const double *p, double *out,
                       src_loc loc);

/* Forgets the lowered pigments (the next scene, an animation's next frame,
 * numbers its pigments anew); keeps the device and program. */
void device_points_forget(device_points *dp);

void device_points_free(device_points *dp);

#endif
