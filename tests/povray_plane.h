/* povray_plane.h: what the device pattern tests (tests/test_pattern.c,
 * tests/test_normal.c) share: the plane z = 0 scene and its camera, the way
 * from the world to a pattern's space, POV-Ray's 16-bit PPM, and a program of
 * the embedded kernels with a test kernel of the test's own, run once a pixel.
 * Each test keeps its cases, how it fills a dev_pattern from one and how it
 * compares its values with POV-Ray's pixels. */
#ifndef ECLAT_POVRAY_PLANE_H
#define ECLAT_POVRAY_PLANE_H

#include <stddef.h>
#include <stdio.h>

#include "device.h"
#include "shared.h"

/* The image POV-Ray renders (tests/pattern.test, tests/normal.test: +W160 +H120). */
#define PLANE_W 160
#define PLANE_H 120
#define PLANE_MAX_WARPS 3

/* A warp as a case writes it; plane_fill_pattern copies it into a dev_warp. */
struct plane_warp {
	int kind, classic;
	float a[4], b[4], c[4];
};

/* The classic turbulence modifier with its defaults: octaves 6, omega 0.5, lambda 2. */
#define PLANE_TURB(t, classic) { WARP_TURBULENCE, classic, { t, t, t, 0.5f }, { 2, 6 }, { 0 } }

/* ---- the scene and its camera ---- */

/* Opens DIR/NAME.pov and writes the version, assumed_gamma 1 and the camera at
 * z = -10 looking at the plane: orthographic, 8 by 6 units, or perspective.
 * Returns NULL after printing why. */
FILE *plane_scene_open(const char *dir, const char *name, int perspective);

/* The point on the plane z = 0 seen through pixel (i, j)'s centre, and the
 * ray's direction. */
void plane_camera_hit(int perspective, int i, int j, double p[3], double d[3]);

/* World to the pattern's space: POV-Ray's scale (scale[0] 0: none), rotate
 * (x, then y, then z) and translate (NULL: a direction, not moved), undone in
 * reverse order. */
void plane_to_pattern(const float scale[3], const float rotate[3], const float *translate, double p[3]);

/* What every case sets the same way: pt zeroed, its kind, wave, noise
 * generator (0: POV-Ray's default, 2), params[0] and params[1] (a gradient's
 * axis normalized, as POV-Ray does), and its n warps at warps[0]. */
void plane_fill_pattern(dev_pattern *pt, dev_warp warps[PLANE_MAX_WARPS], int kind, int wave, int gen,
                        const float p0[4], const float p1[4], const struct plane_warp *w, int n);

/* ---- POV-Ray's image: a binary PPM, 16 bits a channel ---- */

/* Reads DIR/NAME.ppm into out, PLANE_W * PLANE_H pixels of the first channels
 * (1: red, a grey mask; 3: red, green and blue) from 0 to 1. Returns 0, or -1
 * after printing the case's FAIL line. */
int plane_read_case(const char *dir, const char *name, float *out, int channels);

/* ---- the device ---- */

struct plane_device {
	device_ctx d;
	cl_program prog;
	cl_kernel kernel;
};

/* Opens the device and builds the embedded kernels named (in that order) with
 * test_kernel after them, for its kernel kernel_name. who names the test in
 * messages. Returns 0, or -1 after printing why. */
int plane_open(struct plane_device *pd, const char *const *kernels, int n_kernels, const char *test_kernel,
               const char *kernel_name, const char *who);
void plane_close(struct plane_device *pd);

/* One argument of the test kernel: data's size bytes, passed by value or in a
 * read-only buffer. */
struct plane_arg {
	const void *data;
	size_t size;
	int by_value;
};

/* Runs the kernel once a pixel with args and then a buffer of out_size bytes
 * as its last argument, and reads that into out. Returns 0, or -1 after
 * printing why. */
int plane_run(struct plane_device *pd, const struct plane_arg *args, int n_args, void *out, size_t out_size);

/* ---- main ---- */

/* write DIR: calls write_case(DIR, i, &name) for i < n_cases, which writes the
 * case's scene and sets name, or leaves it NULL for a case with no scene, or
 * returns nonzero on an error; and lists the names in DIR/cases.
 * compare DIR: compare(DIR). Returns main's exit status. */
int plane_main(int argc, char **argv, const char *who, int n_cases,
               int (*write_case)(const char *dir, int i, const char **name), int (*compare)(const char *dir));

#endif
