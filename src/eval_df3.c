/* eval_df3.c: POV-Ray's density_file pattern, density_file df3 "File"
 * [interpolate N]. A df3 file is three big-endian 16-bit sizes nx, ny, nz,
 * then nx ny nz voxels, x fastest, then y, then z, each of 1, 2 or 4 bytes,
 * big-endian: the file's length says which (POV-Ray's Read_Density_File).
 * A voxel's value is divided by the largest its width holds (255, 65535,
 * 2^32 - 1), as POV-Ray does. The voxels become a scene image of four voxels
 * a texel, read once however many patterns name the file; kernels/image.cl's
 * density_file_value reads them.
 *
 * The file is the scene's, so untrusted: it is read here, by this code alone
 * (no library to crash), after the path rules every file the scene reads
 * obeys (eval_access), with its sizes checked against its length before
 * anything is allocated, and its memory claimed from the scene's budget. */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "eval_int.h"
#include "loader.h"

/* Four voxels a texel: as many bytes as IMAGE_MAX_TEXELS' largest image. */
#define DF3_MAX_VOXELS (1L << 28)

/* The voxels of the file at path (name, as the scene wrote it, in messages)
 * into im and size; -1 after an error at loc. */
static int df3_read(struct eval *e, const char *path, const char *name, src_loc loc, scene_image *im, long size[3])
{
	const char *not_file = loader_not_a_file(path);
	if (not_file) {
		eval_error(e, loc, "cannot read density_file '%s': it is %s", name, not_file);
		return -1;
	}
	FILE *f = fopen(path, "rb");
	float *v = NULL;
	struct stat st;
	if (!f || fstat(fileno(f), &st) != 0) {
		eval_error(e, loc, "cannot read density_file '%s': %s", name, strerror(errno));
		goto fail;
	}
	unsigned char h[6];
	if (st.st_size < 6 || fread(h, 1, 6, f) != 6) {
		eval_error(e, loc, "density_file '%s' is %lld bytes, too short for a df3 file's 6-byte header", name,
		           (long long)st.st_size);
		goto fail;
	}
	for (int k = 0; k < 3; k++)
		size[k] = h[2 * k] << 8 | h[2 * k + 1];
	if (size[0] == 0 || size[1] == 0 || size[2] == 0) {
		eval_error(e, loc, "density_file '%s' has sizes %ld x %ld x %ld: a df3 file needs at least one voxel",
		           name, size[0], size[1], size[2]);
		goto fail;
	}
	uint64_t n = (uint64_t)size[0] * size[1] * size[2], len = (uint64_t)st.st_size - 6;   /* < 2^48: no overflow */
	int width = len == n ? 1 : len == 2 * n ? 2 : len == 4 * n ? 4 : 0;
	if (!width) {
		eval_error(e, loc, "density_file '%s' has sizes %ld x %ld x %ld, %llu voxels, which take %llu, %llu or "
		           "%llu bytes after the header (1, 2 or 4 a voxel); it has %llu", name, size[0], size[1],
		           size[2], (unsigned long long)n, (unsigned long long)n, (unsigned long long)(2 * n),
		           (unsigned long long)(4 * n), (unsigned long long)len);
		goto fail;
	}
	if (n > DF3_MAX_VOXELS) {
		eval_error(e, loc, "density_file '%s' has %llu voxels, more than eclat's limit of %ld", name,
		           (unsigned long long)n, DF3_MAX_VOXELS);
		goto fail;
	}
	size_t texels = (size_t)(n + 3) / 4;
	if (eval_memory_claim(e, loc, (double)texels * 4 * sizeof(float), "the density_file"))
		goto fail;
	if (!(v = calloc(texels * 4, sizeof *v))) {
		eval_error(e, loc, "out of memory for density_file '%s'", name);
		goto fail;
	}
	double top = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0, sum = 0;
	unsigned char buf[65536];
	uint64_t done = 0;
	while (done < n) {
		size_t want = (size_t)((n - done) * width < sizeof buf ? (n - done) * width : sizeof buf);
		if (fread(buf, 1, want, f) != want) {   /* it shrank since it was measured */
			eval_error(e, loc, "cannot read density_file '%s': it ends early", name);
			goto fail;
		}
		for (size_t i = 0; i < want; i += width, done++) {
			uint32_t x = 0;
			for (int k = 0; k < width; k++)
				x = x << 8 | buf[i + k];
			v[done] = (float)(x / top);
			sum += x / top;
		}
	}
	fclose(f);
	float mean = (float)(sum / n);
	*im = (scene_image){ .rgba = v, .width = (int)texels, .height = 1, .decode = SCENE_DECODE_NONE, .data = true,
	                     .average = { mean, mean, mean, 1 }, .loc = loc };
	return 0;
fail:
	free(v);
	if (f)
		fclose(f);
	return -1;
}

/* The scene image of the file name (looked for as #include looks, then with
 * ".df3" added, as POV-Ray does), read once; -1 after an error at loc. */
static int df3_load(struct eval *e, const char *name, src_loc loc, long size[3])
{
	char *path = eval_find_file(e, loc.file, name);
	if (!path) {
		size_t n = strlen(name) + 5;
		char *with = eval_xrealloc(NULL, n);
		snprintf(with, n, "%s.df3", name);
		path = eval_find_file(e, loc.file, with);
		free(with);
	}
	const char *use = path ? path : name;
	size_t klen = strlen(use) + 8;
	char *key = eval_xrealloc(NULL, klen);
	snprintf(key, klen, "%s\tdf3\t", use);
	scene *s = e->s;
	for (int i = 0; i < s->n_images; i++)
		if (strncmp(s->images[i].key, key, klen - 1) == 0 &&
		    sscanf(s->images[i].key + klen - 1, "%ld %ld %ld", &size[0], &size[1], &size[2]) == 3) {
			free(key);
			free(path);
			return i;
		}
	scene_image im;
	if (eval_access(e, use, false, loc, "a density_file") || df3_read(e, use, name, loc, &im, size)) {
		free(key);
		free(path);
		return -1;
	}
	size_t full = klen + 24;
	im.key = eval_xrealloc(NULL, full);
	snprintf(im.key, full, "%s%ld %ld %ld", key, size[0], size[1], size[2]);
	free(key);
	free(path);
	return scene_add_image(s, &im);
}

int eval_density_file(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg)
{
	int err = 0;
	const ast_node *type = eval_next(c, &err);
	if (!type) {
		if (!err)
			eval_error(e, item->loc, "density_file needs df3 and a file name");
		return -1;
	}
	if (type->kind != AST_IDENT || strcmp(type->str, AST_WORD_DF3) != 0 || eval_lookup(e, type->str)) {
		eval_error(e, type->loc, "expected df3 after density_file (the only format POV-Ray has)");
		return -1;
	}
	const ast_node *file = eval_next_expr(c, &err);
	if (!file) {
		if (!err)
			eval_error(e, type->loc, "density_file df3 needs a file name");
		return -1;
	}
	char *name;
	if (eval_expect_string(e, file, &name))
		return -1;
	long size[3];
	int at = df3_load(e, name, file->loc, size);
	free(name);
	if (at < 0)
		return -1;
	pg->params[0][0] = at;
	for (int k = 0; k < 3; k++)
		pg->params[0][k + 1] = (double)size[k];
	pg->params[1][0] = 0;   /* POV-Ray's default: the nearest voxel */
	return 0;
}

int eval_density_file_interpolate(struct eval *e, const ast_node *arg, scene_pigment *pg)
{
	double v;
	if (eval_expect_float(e, arg, &v))
		return -1;
	/* POV-Ray takes the number modulo 10: 0 nearest, 1 trilinear, any other tricubic */
	int k = eval_int_of(v) % 10;
	pg->params[1][0] = k == 0 ? 0 : k == 1 ? 1 : 2;
	return 0;
}
