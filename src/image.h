/* image.h: image files through OpenImageIO (src/image_oiio.cpp), for C callers. */
#ifndef ECLAT_IMAGE_H
#define ECLAT_IMAGE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes linear RGB (3 floats a pixel, top row first) in the format the file's
 * extension names. PNG, JPEG and other 8-bit formats get the sRGB transfer and are
 * clamped; EXR, HDR, TIFF and PFM stay linear floats, unclamped. The file appears
 * whole or not at all: the image is written to a temporary file beside it and
 * renamed. Returns 0, or -1 with a message in err. */
/* What the file records about the render (EXR keeps it as metadata). */
typedef struct {
	const char *scene;   /* the scene file's name */
	long samples;        /* per pixel */
} image_meta;

int image_write(const char *path, const float *rgb, int width, int height, const image_meta *meta,
                char *err, size_t errlen);

/* The heat map: the BVH tests per pixel per sample. Linear formats get the counts;
 * 8-bit formats a colour map ("turbo") with a legend under it that gives the scale
 * and the units, as in the reference paper's figure. *mean gets the mean. */
int image_write_heat(const char *path, const float *heat, int width, int height, const image_meta *meta,
                     double *mean, char *err, size_t errlen);

/* 1 when the extension of path names a format OpenImageIO can write. */
int image_format_known(const char *path);

#ifdef __cplusplus
}
#endif

#endif
