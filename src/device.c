/* device.c: OpenCL platform and device selection and program building. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "diag.h"

#define MAX_DEVICES 64

const char *device_error_name(cl_int err)
{
	switch (err) {
#define E(x) case x: return #x;
	E(CL_DEVICE_NOT_FOUND) E(CL_DEVICE_NOT_AVAILABLE) E(CL_COMPILER_NOT_AVAILABLE)
	E(CL_MEM_OBJECT_ALLOCATION_FAILURE) E(CL_OUT_OF_RESOURCES) E(CL_OUT_OF_HOST_MEMORY)
	E(CL_BUILD_PROGRAM_FAILURE) E(CL_INVALID_VALUE) E(CL_INVALID_DEVICE) E(CL_INVALID_CONTEXT)
	E(CL_INVALID_BINARY) E(CL_INVALID_BUILD_OPTIONS) E(CL_INVALID_PROGRAM)
	E(CL_INVALID_KERNEL_NAME) E(CL_INVALID_KERNEL_ARGS) E(CL_INVALID_WORK_GROUP_SIZE)
	E(CL_INVALID_BUFFER_SIZE) E(CL_INVALID_GLOBAL_WORK_SIZE) E(CL_INVALID_MEM_OBJECT)
	E(CL_INVALID_ARG_INDEX) E(CL_INVALID_ARG_VALUE) E(CL_INVALID_ARG_SIZE)
	E(CL_INVALID_COMMAND_QUEUE) E(CL_INVALID_OPERATION)
#undef E
	case -1001: return "CL_PLATFORM_NOT_FOUND_KHR";
	default: return "unknown OpenCL error";
	}
}

int device_fail(const char *call, cl_int err)
{
	fprintf(stderr, "eclat: %s failed: %s (%d)\n", call, device_error_name(err), err);
	return -1;
}

/* Every device of every platform, in platform order: the numbering of --device. */
static int all_devices(cl_device_id *out, cl_platform_id *platform_of)
{
	cl_platform_id platforms[16];
	cl_uint np = 0;
	cl_int err = clGetPlatformIDs(16, platforms, &np);
	if (err == -1001 || (err == CL_SUCCESS && np == 0)) {
		fprintf(stderr, "eclat: no OpenCL platform found; install one, for example "
		                "'apt-get install pocl-opencl-icd' for the CPU\n");
		return -1;
	}
	if (err != CL_SUCCESS)
		return device_fail("clGetPlatformIDs", err);
	int n = 0;
	for (cl_uint p = 0; p < np && n < MAX_DEVICES; p++) {
		cl_uint nd = 0;
		if (clGetDeviceIDs(platforms[p], CL_DEVICE_TYPE_ALL, MAX_DEVICES - n, out + n, &nd) != CL_SUCCESS)
			continue;
		for (cl_uint i = 0; i < nd; i++)
			platform_of[n + i] = platforms[p];
		n += nd;
	}
	if (n == 0) {
		fprintf(stderr, "eclat: the OpenCL platforms have no devices; install one, for example "
		                "'apt-get install pocl-opencl-icd' for the CPU\n");
		return -1;
	}
	return n;
}

static cl_device_type device_type(cl_device_id d)
{
	cl_device_type t = 0;
	clGetDeviceInfo(d, CL_DEVICE_TYPE, sizeof t, &t, NULL);
	return t;
}

int device_count(void)
{
	cl_device_id devs[MAX_DEVICES];
	cl_platform_id plats[MAX_DEVICES];
	return all_devices(devs, plats);
}

int device_list(FILE *out)
{
	cl_device_id devs[MAX_DEVICES];
	cl_platform_id plats[MAX_DEVICES];
	int n = all_devices(devs, plats);
	for (int i = 0; i < n; i++) {
		char pname[128] = "", dname[128] = "", version[128] = "";
		cl_uint units = 0;
		clGetPlatformInfo(plats[i], CL_PLATFORM_NAME, sizeof pname, pname, NULL);
		clGetDeviceInfo(devs[i], CL_DEVICE_NAME, sizeof dname, dname, NULL);
		clGetDeviceInfo(devs[i], CL_DEVICE_VERSION, sizeof version, version, NULL);
		clGetDeviceInfo(devs[i], CL_DEVICE_MAX_COMPUTE_UNITS, sizeof units, &units, NULL);
		cl_device_type t = device_type(devs[i]);
		fprintf(out, "%d: %s: %s (%s, %s, %u compute units)\n", i, pname, dname,
		        t & CL_DEVICE_TYPE_GPU ? "GPU" : t & CL_DEVICE_TYPE_CPU ? "CPU" : "accelerator",
		        version, units);
	}
	return n;
}

static int default_device(cl_device_id *devs, int n)
{
	for (int i = 0; i < n; i++)
		if (device_type(devs[i]) & CL_DEVICE_TYPE_GPU)
			return i;
	for (int i = 0; i < n; i++)
		if (device_type(devs[i]) & CL_DEVICE_TYPE_CPU)
			return i;
	return 0;
}

int device_open(device_ctx *d, int index)
{
	memset(d, 0, sizeof *d);
	cl_device_id devs[MAX_DEVICES];
	cl_platform_id plats[MAX_DEVICES];
	int n = all_devices(devs, plats);
	if (n < 0)
		return -1;
	if (index >= n) {
		fprintf(stderr, "eclat: there is no device %d (eclat --list-devices shows %d)\n", index, n);
		return -1;
	}
	int i = index < 0 ? default_device(devs, n) : index;
	d->device = devs[i];
	clGetDeviceInfo(d->device, CL_DEVICE_NAME, sizeof d->name, d->name, NULL);
	clGetDeviceInfo(d->device, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof d->global_mem, &d->global_mem, NULL);
	clGetDeviceInfo(d->device, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof d->max_alloc, &d->max_alloc, NULL);
	cl_context_properties props[] = { CL_CONTEXT_PLATFORM, (cl_context_properties)plats[i], 0 };
	cl_int err;
	d->context = clCreateContext(props, 1, &d->device, NULL, NULL, &err);
	if (!d->context)
		return device_fail("clCreateContext", err);
	d->queue = clCreateCommandQueue(d->context, d->device, 0, &err);
	if (!d->queue)
		return device_fail("clCreateCommandQueue", err);
	return 0;
}

/* Reads kernel_dir/BASENAME for each embedded source, with a #line naming it. */
static char **read_sources(const char *kernel_dir, int n)
{
	char **texts = calloc(n, sizeof *texts);
	for (int i = 0; texts && i < n; i++) {
		const char *base = strrchr(device_sources[i].name, '/');
		char path[4096];
		snprintf(path, sizeof path, "%s/%s", kernel_dir, base ? base + 1 : device_sources[i].name);
		size_t len;
		char *body = diag_read_file(path, &len);
		if (!body) {
			fprintf(stderr, "eclat: cannot read kernel source '%s': %s\n", path, strerror(errno));
			for (int k = 0; k < i; k++)
				free(texts[k]);
			free(texts);
			return NULL;
		}
		size_t size = len + strlen(path) + 16;
		texts[i] = malloc(size);
		if (texts[i])
			snprintf(texts[i], size, "#line 1 \"%s\"\n%s", path, body);
		free(body);
	}
	return texts;
}

static void print_build_log(device_ctx *d, cl_program prog)
{
	size_t size = 0;
	clGetProgramBuildInfo(prog, d->device, CL_PROGRAM_BUILD_LOG, 0, NULL, &size);
	char *log = malloc(size + 1);
	if (!log)
		return;
	log[0] = '\0';
	clGetProgramBuildInfo(prog, d->device, CL_PROGRAM_BUILD_LOG, size, log, NULL);
	log[size] = '\0';
	fprintf(stderr, "eclat: the kernels failed to build for %s:\n%s\n", d->name, log);
	free(log);
}

cl_program device_build(device_ctx *d, const char *kernel_dir, const char *options, const char *extra)
{
	int n = 0;
	while (device_sources[n].name)
		n++;
	char **disk = kernel_dir ? read_sources(kernel_dir, n) : NULL;
	if (kernel_dir && !disk)
		return NULL;
	const char *texts[64];
	for (int i = 0; i < n && i < 63; i++)
		texts[i] = disk ? disk[i] : device_sources[i].text;
	if (extra)
		texts[n++] = extra;
	cl_int err;
	cl_program prog = clCreateProgramWithSource(d->context, n, texts, NULL, &err);
	for (int i = 0; disk && i < n - (extra != NULL); i++)
		free(disk[i]);
	free(disk);
	if (!prog) {
		device_fail("clCreateProgramWithSource", err);
		return NULL;
	}
	/* PoCL compiles each kernel at its first launch, in a time set by the depth of its
	 * out-of-line calls: every helper in kernels/ is static (doc/DESIGN.md). */
	err = clBuildProgram(prog, 1, &d->device, options, NULL, NULL);
	if (err != CL_SUCCESS) {
		if (err == CL_BUILD_PROGRAM_FAILURE)
			print_build_log(d, prog);
		else
			device_fail("clBuildProgram", err);
		clReleaseProgram(prog);
		return NULL;
	}
	return prog;
}

void device_close(device_ctx *d)
{
	if (d->queue)
		clReleaseCommandQueue(d->queue);
	if (d->context)
		clReleaseContext(d->context);
	memset(d, 0, sizeof *d);
}
