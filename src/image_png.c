/* image_png.c: the palette indices of a colormapped PNG, through libpng, for a
 * height_field: POV-Ray takes an indexed image's heights from its indices, not
 * its colours, and OpenImageIO gives only the colours. */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>

#include "image.h"

int image_png_indices_here(const char *path, long max_texels, unsigned char **out, int *width, int *height)
{
	*out = NULL;
	FILE *f = fopen(path, "rb");
	if (!f)
		return 0;
	unsigned char sig[8];
	if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8)) {
		fclose(f);
		return 0;
	}
	png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	png_infop info = png ? png_create_info_struct(png) : NULL;
	unsigned char *pixels = NULL;
	png_bytep *rows = NULL;
	int rc = 0;
	if (!info || setjmp(png_jmpbuf(png))) {   /* a broken file: not indexed, as far as we know */
		free(pixels);
		free(rows);
		png_destroy_read_struct(&png, &info, NULL);
		fclose(f);
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
			rc = 1;
		}
	}
	free(pixels);
	free(rows);
	png_destroy_read_struct(&png, &info, NULL);
	fclose(f);
	return rc;
}
