/* fault_shim.c: LD_PRELOADed by tests/hostile.tap to make a library misbehave
 * as a hostile file might make it: ECLAT_FAULT=crash or hang, in FreeType's
 * FT_New_Face (a font) or libpng's png_read_info (a PNG, through OpenImageIO).
 * eclat runs those libraries in a child process (src/loader.c): the test shows
 * a crash or a hang there is an error at the scene's line, not eclat's end. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void misbehave(void)
{
	const char *f = getenv("ECLAT_FAULT");
	if (f && strcmp(f, "crash") == 0)
		raise(SIGSEGV);
	if (f && strcmp(f, "hang") == 0)
		for (;;)
			pause();
}

typedef int (*ft_new_face_fn)(void *, const char *, long, void *);

int FT_New_Face(void *lib, const char *path, long index, void *face)
{
	misbehave();
	ft_new_face_fn next = (ft_new_face_fn)dlsym(RTLD_NEXT, "FT_New_Face");
	return next(lib, path, index, face);
}

typedef void (*png_read_info_fn)(void *, void *);

void png_read_info(void *png, void *info)
{
	misbehave();
	png_read_info_fn next = (png_read_info_fn)dlsym(RTLD_NEXT, "png_read_info");
	next(png, info);
}
