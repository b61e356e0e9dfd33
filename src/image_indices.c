/* image_indices.c: the palette indices of a colormapped PNG (libpng) or of a
 * GIF (giflib), for a height_field and a material_map: POV-Ray takes an
 * indexed image's heights and materials from its indices, not its colours,
 * and OpenImageIO gives only the colours. */
#include <gif_lib.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"

/* A GIF's first image, as POV-Ray reads it (gif.cpp): its own descriptor's
 * size, top row first; giflib's DGifSlurp puts interlaced rows in order. */
static int gif_indices(const char *path, long max_texels, unsigned char **out, int *width, int *height)
{
	int err;
	GifFileType *gif = DGifOpenFileName(path, &err);
	if (!gif)
		return 0;
	int rc = 0;
	if (DGifSlurp(gif) == GIF_OK && gif->ImageCount > 0) {
		const SavedImage *im = &gif->SavedImages[0];
		long w = im->ImageDesc.Width, h = im->ImageDesc.Height;
		if (w > 0 && h > 0 && w * h <= max_texels && im->RasterBits && (*out = malloc((size_t)(w * h)))) {
			memcpy(*out, im->RasterBits, (size_t)(w * h));
			*width = (int)w;
			*height = (int)h;
			rc = IMAGE_INDICES_GIF;
		}
	}
	DGifCloseFile(gif, &err);
	return rc;
}

/* A colormapped PNG's, from f past its signature. pixels and rows are
 * volatile: libpng's errors come back through longjmp, which frees them. */
static int png_indices(FILE *f, long max_texels, unsigned char **out, int *width, int *height)
{
	png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	png_infop info = png ? png_create_info_struct(png) : NULL;
	unsigned char *volatile pixels = NULL;
	png_bytep *volatile rows = NULL;
	int rc = 0;
	if (!info || setjmp(png_jmpbuf(png))) {   /* a broken file: not indexed, as far as we know */
		free(pixels);
		free(rows);
		png_destroy_read_struct(&png, &info, NULL);
		return 0;
	}
	png_init_io(png, f);
	png_set_sig_bytes(png, 8);
	png_read_info(png, info);
	png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
	if (png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE && w > 0 && h > 0 &&
	    (long)w * (long)h <= max_texels) {
		png_set_packing(png);   /* indices below 8 bits, one a byte */
		png_read_update_info(png, info);
		pixels = malloc((size_t)w * h);
		rows = malloc(h * sizeof *rows);
		if (pixels && rows) {
			for (png_uint_32 y = 0; y < h; y++)
				rows[y] = pixels + (size_t)y * w;
			png_read_image(png, rows);
			*out = pixels;
			pixels = NULL;
			*width = (int)w;
			*height = (int)h;
			rc = IMAGE_INDICES_PNG;
		}
	}
	free(pixels);
	free(rows);
	png_destroy_read_struct(&png, &info, NULL);
	return rc;
}

int image_indices_here(const char *path, long max_texels, unsigned char **out, int *width, int *height)
{
	*out = NULL;
	FILE *f = fopen(path, "rb");
	if (!f)
		return 0;
	unsigned char sig[8] = { 0 };
	int rc = 0;
	if (fread(sig, 1, 8, f) == 8 && !png_sig_cmp(sig, 0, 8))
		rc = png_indices(f, max_texels, out, width, height);
	fclose(f);
	if (memcmp(sig, "GIF8", 4) == 0)
		rc = gif_indices(path, max_texels, out, width, height);
	return rc;
}
