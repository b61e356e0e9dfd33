/* image_table.c: the table that eclat-oiio.so exports (src/image_table.h).
 * Built only into the module, with every other symbol hidden. */
#include "image_table.h"

__attribute__((visibility("default"))) const image_table *eclat_image_table(void)
{
	static const image_table t = {
		IMAGE_TABLE_ABI, sizeof(image_table), sizeof(image_meta), sizeof(image_data), sizeof(split_info),
		image_format_known, image_format_alpha, image_temp_path, image_finish, image_write, image_encode8,
		image_write_heat, image_read_here, split_write, split_read_here,
	};
	return &t;
}
