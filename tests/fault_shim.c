/* fault_shim.c: LD_PRELOADed by tests/hostile.tap to make a library misbehave
 * as a hostile file might make it: ECLAT_FAULT=crash or hang, in FreeType's
 * FT_New_Face (a font) or libpng's png_read_info (a PNG, through OpenImageIO).
 * eclat runs those libraries in a child process (src/loader.c): the test shows
 * a crash or a hang there is an error at the scene's line, not eclat's end.
 * ECLAT_FAULT=enospc: a disk that is full under the folder ECLAT_FAULT_PATH
 * (tests/faults.tap): write(), writev() and fwrite() to a file there fail
 * with ENOSPC (libstdc++'s streams, which OpenEXR's multi-part files use,
 * write with writev),
 * as they would when a render's output folder fills up (a tmpfs would need
 * root). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/uio.h>
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

/* A file descriptor open under ECLAT_FAULT_PATH, with ECLAT_FAULT=enospc. */
static int full(int fd)
{
	const char *f = getenv("ECLAT_FAULT"), *under = getenv("ECLAT_FAULT_PATH");
	if (!f || strcmp(f, "enospc") != 0 || !under || !*under || fd < 0)
		return 0;
	char link[64], path[4096];
	snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
	ssize_t n = readlink(link, path, sizeof path - 1);
	if (n <= 0)
		return 0;
	path[n] = '\0';
	return strncmp(path, under, strlen(under)) == 0;
}

typedef ssize_t (*write_fn)(int, const void *, size_t);

ssize_t write(int fd, const void *buf, size_t n)
{
	if (full(fd)) {
		errno = ENOSPC;
		return -1;
	}
	write_fn next = (write_fn)dlsym(RTLD_NEXT, "write");
	return next(fd, buf, n);
}

typedef size_t (*fwrite_fn)(const void *, size_t, size_t, FILE *);

size_t fwrite(const void *p, size_t size, size_t n, FILE *stream)
{
	if (full(fileno(stream))) {
		errno = ENOSPC;
		return 0;
	}
	fwrite_fn next = (fwrite_fn)dlsym(RTLD_NEXT, "fwrite");
	return next(p, size, n, stream);
}

typedef ssize_t (*writev_fn)(int, const struct iovec *, int);

ssize_t writev(int fd, const struct iovec *iov, int n)
{
	if (full(fd)) {
		errno = ENOSPC;
		return -1;
	}
	writev_fn next = (writev_fn)dlsym(RTLD_NEXT, "writev");
	return next(fd, iov, n);
}
