/* render_keep.c: the device, kernels and BVHs an animation's frames share.
 * Building the kernels takes seconds on PoCL, longer than a small frame, so a
 * frame whose generated source is the previous one's reuses its program. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_keep.h"

lower_cache *render_keep_cache(render_keep *k)
{
	if (!k->bvhs)
		k->bvhs = lower_cache_new();
	return k->bvhs;
}

/* What the program is made of besides the kernels' files, which do not
 * change while eclat runs: the build options and the scene's functions. */
static char *program_key(const lower_result *lr)
{
	const char *opts = lower_kernel_options(lr), *fns = lr->functions ? lr->functions : "";
	size_t a = strlen(opts), b = strlen(fns);
	char *key = malloc(a + b + 2);
	if (key) {
		memcpy(key, opts, a);
		key[a] = '\n';
		memcpy(key + a + 1, fns, b + 1);
	}
	return key;
}

cl_program render_keep_program(render_keep *k, int index, const char *kernel_dir, const lower_result *lr)
{
	if (k->opened == 0)
		k->opened = device_open(&k->dev, index) == 0 ? 1 : -1;
	if (k->opened < 0)
		return NULL;
	char *key = program_key(lr);
	if (!key) {
		fprintf(stderr, "eclat: out of memory\n");
		return NULL;
	}
	if (k->prog && strcmp(key, k->prog_key) == 0) {
		free(key);
		return k->prog;
	}
	if (k->prog)
		clReleaseProgram(k->prog);
	free(k->prog_key);
	k->prog_key = key;
	k->prog = device_build(&k->dev, kernel_dir, lower_kernel_options(lr), lr->functions);
	k->builds += k->prog != NULL;
	return k->prog;
}

void render_keep_free(render_keep *k)
{
	if (k->prog)
		clReleaseProgram(k->prog);
	if (k->opened > 0)
		device_close(&k->dev);
	free(k->prog_key);
	lower_cache_free(k->bvhs);
	memset(k, 0, sizeof *k);
}
