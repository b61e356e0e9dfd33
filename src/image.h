/* image.h: image files through OpenImageIO (src/image_oiio.cpp), for C callers. */
#ifndef ECLAT_IMAGE_H
#define ECLAT_IMAGE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes linear RGB (3 floats a pixel, top row first) in the format the file's
 * extension names. PNG, JPEG and other 8-bit formats get the sRGB transfer and are
 * clamped; EXR, HDR and TIFF stay linear floats, unclamped. The file appears
 * whole or not at all: the image is written to a temporary file beside it and
 * renamed. Returns 0, or -1 with a message in err. */
/* What the file records about the render (EXR keeps it as metadata). */
typedef struct {
	const char *scene;   /* the scene file's name */
	long samples;        /* per pixel */
	int bits;            /* 16: 16 bits a channel in PNG and PPM; 0 or 8: 8 */
	const float *alpha;  /* NULL, or one a pixel: the image gets an alpha channel, the colours
	                      * being associated with it (black where alpha is 0); 8- and 16-bit
	                      * formats store them divided by alpha, as PNG wants them */
} image_meta;

/* The temporary file beside path that an image is written to before its
 * rename (beside it, so the rename cannot cross file systems). */
void image_temp_path(const char *path, char *out, size_t n);
/* Ends the write of tmp into path: when the writer failed (write_error, its
 * message) or the file is not on the disk whole (a full disk a writer did not
 * notice: synced and read back as width x height), tmp is removed and -1
 * returned with err; else tmp is renamed to path. */
int image_finish(const char *tmp, const char *path, const char *write_error, int width, int height,
                 char *err, size_t errlen);
int image_write(const char *path, const float *rgb, int width, int height, const image_meta *meta,
                char *err, size_t errlen);

/* What an 8-bit image file holds for n linear values (3 a pixel): the sRGB
 * transfer, the clamp and the rounding image_write gives them, so that the
 * preview window (src/preview.c) shows the written image's bytes. */
void image_encode8(const float *linear, size_t n, unsigned char *out);

/* The heat map: the BVH tests per pixel per sample. Linear formats get the counts;
 * 8-bit formats a colour map ("turbo") with a legend under it that gives the scale
 * and the units, as in the reference paper's figure. *mean gets the mean. */
int image_write_heat(const char *path, const float *heat, int width, int height, const image_meta *meta,
                     double *mean, char *err, size_t errlen);

/* An image read for a pigment's image_map: RGBA floats, top row first, as the
 * file stores them (no colour conversion; alpha 1 where the file has none; a
 * grey image's value in r, g and b). What the file says of its encoding:
 * IMAGE_GAMMA_SRGB (OpenImageIO names it sRGB), IMAGE_GAMMA_POWER (a gamma
 * gamma, PNG's gAMA), IMAGE_GAMMA_LINEAR (float formats), IMAGE_GAMMA_UNKNOWN.
 * format: OpenImageIO's name for it ("png", "openexr"...); premultiplied: the
 * file's alpha is associated (OpenEXR's). */
enum { IMAGE_GAMMA_UNKNOWN, IMAGE_GAMMA_SRGB, IMAGE_GAMMA_POWER, IMAGE_GAMMA_LINEAR };
typedef struct {
	float *rgba;
	int width, height;
	int encoding;        /* IMAGE_GAMMA_ */
	float gamma;         /* IMAGE_GAMMA_POWER's: 2.2 */
	int premultiplied;
	char format[32];
	int channels;        /* in the file: 1 or 2 for a grey image */
	int bits;            /* per channel in the file: 8, 16, 32 */
} image_data;

/* Reads path; refuses, from the file's header and before decoding, an image of
 * more than max_texels pixels or IMAGE_MAX_SIDE on a side, saying so with the
 * numbers, and pixels that would take more than max_bytes here. OpenImageIO
 * runs in a child process (src/image_child.c) given time_limit seconds (0: no
 * limit), so a decoder that crashes or hangs is an error. Returns 0, or -1 with the reason in err. Free the pixels with free().
 * image_read_here does the same in this process (the child's work, and the
 * fuzz target's). */
#define IMAGE_MAX_SIDE 65536
typedef struct {
	long max_texels;
	unsigned time_limit;
	double max_bytes;   /* the memory the pixels may take here (16 bytes each); 0: no limit */
} image_limits;
int image_read(const char *path, const image_limits *lim, image_data *out, char *err, size_t errlen);
int image_read_here(const char *path, long max_texels, image_data *out, char *err, size_t errlen);

/* A colormapped PNG's or a GIF's palette indices, top row first, one byte a
 * pixel (free() them): IMAGE_INDICES_PNG or _GIF, or 0 when the file is no
 * such image (or not one of at most max_texels pixels, or unreadable:
 * image_read says why). libpng and giflib (src/image_indices.c), in a child
 * process as image_read's decoder is. */
enum { IMAGE_INDICES_PNG = 1, IMAGE_INDICES_GIF = 2 };
int image_indices(const char *path, const image_limits *lim, unsigned char **out, int *width, int *height);
int image_indices_here(const char *path, long max_texels, unsigned char **out, int *width, int *height);
/* 1 when the extension of path names a format OpenImageIO can write. */
int image_format_known(const char *path);
/* 1 when that format can hold an alpha channel. */
int image_format_alpha(const char *path);

#ifdef __cplusplus
}
#endif

#endif
