/* device.h: the OpenCL platform, device, context and program. */
#ifndef ECLAT_DEVICE_H
#define ECLAT_DEVICE_H

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
#include <stdio.h>

/* The kernel sources in program order, embedded at build time (kernels_embed.c). */
struct device_source {
	const char *name;  /* path relative to the source tree, e.g. "kernels/rng.cl" */
	const char *text;
};
extern const struct device_source device_sources[];

typedef struct {
	cl_device_id device;
	cl_context context;
	cl_command_queue queue;
	char name[256];
	cl_ulong global_mem, max_alloc;
} device_ctx;

/* Prints every device of every platform with its index for --device. Returns the
 * number of devices, or -1 when there is no platform (the message is printed). */
int device_list(FILE *out);
/* The number of devices (--device all), or -1 when there is no platform (said). */
int device_count(void);

/* index < 0: the first GPU, else the first CPU device, else the first device.
 * Returns 0, or -1 after printing why. */
int device_open(device_ctx *d, int index);

/* Builds the program from the embedded sources, or from the same files under
 * kernel_dir when it is not NULL, then extra when it is not NULL (the scene's
 * functions, lower_result.functions). Returns NULL after printing the build log. */
cl_program device_build(device_ctx *d, const char *kernel_dir, const char *options, const char *extra);

void device_close(device_ctx *d);

/* "CL_OUT_OF_RESOURCES" for -5, and so on. */
const char *device_error_name(cl_int err);

/* Prints "eclat: CALL failed: NAME" and returns -1, for one-line error paths. */
int device_fail(const char *call, cl_int err);

#endif
