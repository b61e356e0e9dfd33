/* image_module.c: eclat's image functions (image.h, split.h) as calls into its
 * module eclat-oiio.so, which alone links OpenImageIO (src/image_table.h says
 * why). The module is looked for beside the binary (a build tree), then in
 * PKGLIBDIR as it is for the running binary (src/install_path.c). It loads
 * once: on a thread of its own from image_module_start, which main calls when
 * a render will write an image, so that the load overlaps the reading of the
 * scene; else at the first call. A load under way ends before every loader
 * fork (a child must not inherit it half made) and before every exit, main's
 * return (image_module_settle) and diag_exit alike: exit() runs the
 * destructors that the libraries' constructors have registered so far, and
 * with the load under way, others of those constructors are still running
 * (gdcm's asserted, in a scene with a syntax error). */
#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "diag.h"
#include "image_table.h"
#include "install_path.h"
#include "loader.h"

#ifndef ECLAT_PKGLIBDIR   /* set by Makefile.am; this keeps other builds compiling */
#define ECLAT_PKGLIBDIR "/usr/local/lib/eclat"
#endif

static pthread_once_t once = PTHREAD_ONCE_INIT;
static const image_table *table;
static char why[PATH_MAX + 600];
static int started;   /* a thread was started to load it */

/* The module at path, or NULL with the reason in why. */
static const image_table *try_load(const char *path)
{
	void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
	if (!h) {
		const char *e = dlerror();
		snprintf(why, sizeof why, "cannot load eclat's image module: %s", e ? e : path);
		return NULL;
	}
	const image_table *(*get)(void) = (const image_table *(*)(void))dlsym(h, IMAGE_TABLE_SYMBOL);
	const image_table *t = get ? get() : NULL;
	if (!t || t->abi != IMAGE_TABLE_ABI || t->size != sizeof(image_table) || t->meta_size != sizeof(image_meta) ||
	    t->data_size != sizeof(image_data) || t->split_size != sizeof(split_info)) {
		snprintf(why, sizeof why, "cannot load eclat's image module: %s is not this eclat's", path);
		dlclose(h);
		return NULL;
	}
	return t;
}

static void load(void)
{
	char dir[PATH_MAX], path[PATH_MAX + 32];
	if (install_exe_dir(dir, sizeof dir) == 0) {
		snprintf(path, sizeof path, "%s/%s", dir, IMAGE_MODULE_NAME);
		FILE *f = fopen(path, "rb");   /* only a module that is there: else the installed one's error */
		if (f) {
			fclose(f);
			if ((table = try_load(path)))
				return;
		}
	}
	install_path(ECLAT_PKGLIBDIR, dir, sizeof dir);
	snprintf(path, sizeof path, "%s/%s", dir, IMAGE_MODULE_NAME);
	table = try_load(path);
}

static const image_table *module(void)
{
	pthread_once(&once, load);
	return table;
}

/* The thread loads the module, then stays until eclat exits: the libraries'
 * initialisers allocate data of the thread that runs them (log4cplus, SRT),
 * which the exit of the thread would leave unreachable, as valgrind and
 * LeakSanitizer would say. It takes no signal (they are blocked when it is
 * made): they stay the main thread's. */
static void *load_thread(void *arg)
{
	(void)arg;
	module();
	for (;;)
		pause();
	return NULL;
}

/* Images are read in children (src/image_child.c, src/split_child.c): the
 * module is loaded first, once, rather than in each child. */
static void before_fork(const char *library)
{
	if (strcmp(library, "OpenImageIO") == 0 || strcmp(library, "OpenEXR") == 0 || started)
		module();
}

__attribute__((constructor)) static void set_hooks(void)
{
	loader_before_fork = before_fork;
	diag_before_exit = image_module_settle;
}

void image_module_start(void)
{
	pthread_t th;
	if (started)
		return;
	pthread_attr_t attr;
	sigset_t all, was;
	sigfillset(&all);
	pthread_attr_init(&attr);
	pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
	pthread_sigmask(SIG_SETMASK, &all, &was);
	started = pthread_create(&th, &attr, load_thread, NULL) == 0;
	pthread_sigmask(SIG_SETMASK, &was, NULL);
	pthread_attr_destroy(&attr);
}

void image_module_settle(void)
{
	if (started)
		module();
}

const char *image_module_error(void)
{
	return module() ? NULL : why;
}

static int fail(char *err, size_t errlen)
{
	snprintf(err, errlen, "%s", why);
	return -1;
}

int image_format_known(const char *path)
{
	return module() ? table->format_known(path) : 0;
}

int image_format_alpha(const char *path)
{
	return module() ? table->format_alpha(path) : 0;
}

void image_temp_path(const char *path, char *out, size_t n)
{
	if (module())
		table->temp_path(path, out, n);
	else
		snprintf(out, n, "%s.tmp", path);
}

int image_finish(const char *tmp, const char *path, const char *write_error, int width, int height, char *err,
                 size_t errlen)
{
	return module() ? table->finish(tmp, path, write_error, width, height, err, errlen) : fail(err, errlen);
}

int image_write(const char *path, const float *rgb, int width, int height, const image_meta *meta, char *err,
                size_t errlen)
{
	return module() ? table->write(path, rgb, width, height, meta, err, errlen) : fail(err, errlen);
}

void image_encode8(const float *linear, size_t n, unsigned char *out)
{
	if (module())
		table->encode8(linear, n, out);
	else
		memset(out, 0, n);
}

int image_write_heat(const char *path, const float *heat, int width, int height, const image_meta *meta,
                     double *mean, char *err, size_t errlen)
{
	return module() ? table->write_heat(path, heat, width, height, meta, mean, err, errlen) : fail(err, errlen);
}

int image_read_here(const char *path, long max_texels, image_data *out, char *err, size_t errlen)
{
	return module() ? table->read_here(path, max_texels, out, err, errlen) : fail(err, errlen);
}

int split_write(const char *path, const float *rgb, const int64_t *sums, const split_info *info, char *err,
                size_t errlen)
{
	return module() ? table->split_write(path, rgb, sums, info, err, errlen) : fail(err, errlen);
}

int split_read_here(const char *path, split_info *info, int64_t **sums, char *err, size_t errlen)
{
	return module() ? table->split_read_here(path, info, sums, err, errlen) : fail(err, errlen);
}
