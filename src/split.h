/* split.h: what an EXR of a render records so that renders split into sample
 * ranges and regions merge exactly (src/merge.c) and interrupted ones resume:
 * the scene's content (a hash of every file it read), the options that change
 * pixels, and which samples of which pixels the file's exact sums hold. */
#ifndef ECLAT_SPLIT_H
#define ECLAT_SPLIT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The files a scene read, as eval reported them (eval_options.on_read). */
typedef struct {
	char **paths;   /* resolved, each once */
	int n, cap;
} split_inputs;

void split_note_input(const char *path, void *inputs);
void split_inputs_free(split_inputs *in);

/* What must be equal for two files' samples to belong to one image. Both are
 * lines: options "name=value\n", files "HASH PATH\n" (the scene first). */
typedef struct {
	char *options, *files;
} split_key;

/* Hashes the scene and each input. Returns 0, or -1 after saying which file
 * could not be read. */
int split_key_make(split_key *k, const char *scene, const split_inputs *in, const char *options);
void split_key_free(split_key *k);
/* 0 when was and now are the same scene and options; else 1, with the first
 * difference in why ("'x.inc' changed", "--seed was 1, is 2"). */
int split_key_diff(const split_key *was, const split_key *now, char *why, size_t n);

/* An EXR's record of its render. */
typedef struct {
	split_key key;
	char *scene;         /* the scene file's name, as given */
	int width, height;
	long total;          /* samples per pixel of the whole render (-s) */
	long first, count;   /* the sample range it renders (--sample-range) */
	long samples;        /* samples of that range done: count when finished */
	int region[4];       /* the pixels it renders: left, top, right, bottom, inclusive */
	float gamma;         /* the scene's working gamma, which the image is resolved with */
} split_info;

void split_info_free(split_info *info);
/* 1 when pixel (x, y) is in info's region. */
int split_in_region(const split_info *info, int x, int y);

/* Writes the image (rgb, 3 floats a pixel) with the film's exact sums (4 a
 * pixel, FILM_FRACTION_BITS) and info in an EXR, atomically, as image_write
 * does (src/image_split.cpp). Returns 0, or -1 with a message in err. */
int split_write(const char *path, const float *rgb, const int64_t *sums, const split_info *info, char *err,
                size_t errlen);
/* Reads what split_write wrote: info and the sums (malloc'ed). Returns 0, or -1
 * with the problem in err: not an image, not an EXR of eclat's, truncated, too
 * large for the memory left. OpenEXR reads the file in a child process
 * (src/split_child.c): the parts of a split render come from other machines,
 * and a hostile one must not end eclat. */
int split_read(const char *path, split_info *info, int64_t **sums, char *err, size_t errlen);
/* The same, in this process (src/image_split.cpp): what the child runs. */
int split_read_here(const char *path, split_info *info, int64_t **sums, char *err, size_t errlen);
/* 0 when a width x height image's sums fit in 65536 on a side and in the memory
 * left; else -1 with the numbers in err. */
int split_size_check(long width, long height, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
