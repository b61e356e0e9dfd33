// image_split.cpp: EXRs that carry a render's exact sums and its record
// (src/split.h), through OpenImageIO. The image is the file's first part, as
// in any EXR, with the record as metadata; the sums are a second part, where
// viewers and image comparisons do not look. They are 64-bit integers; EXR has
// no such channel, so each is kept as three float channels of 22, 22 and 20
// bits, which floats hold exactly, in a lossless compression.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

#include "image.h"
#include "split.h"

using namespace OIIO;

static const char *const sum_names[4] = { "R", "G", "B", "tests" };
enum { SUM_CHANNELS = 12, CHUNK_BITS = 22 };

static int fail(char *err, size_t errlen, const std::string &msg)
{
	std::snprintf(err, errlen, "%s", msg.c_str());
	return -1;
}

static std::string sum_channel(int i)
{
	return std::string("eclat.sum.") + sum_names[i / 3] + "." + char('0' + i % 3);
}

static void to_chunks(int64_t v, float *out)
{
	uint64_t u = (uint64_t)v;
	for (int k = 0; k < 3; k++, u >>= CHUNK_BITS)
		out[k] = (float)(u & ((1u << CHUNK_BITS) - 1));
}

static int64_t from_chunks(const float *in)
{
	uint64_t u = 0;
	for (int k = 2; k >= 0; k--)
		u = u << CHUNK_BITS | (uint64_t)in[k];
	return (int64_t)u;
}

extern "C" int split_write(const char *path, const float *rgb, const int64_t *sums, const split_info *info,
                           char *err, size_t errlen)
{
	std::string p(path);
	auto out = ImageOutput::create(p);
	if (!out)
		return fail(err, errlen, "cannot write '" + p + "': no image format for this extension");
	if (!out->supports("multiimage"))
		return fail(err, errlen, "cannot write '" + p + "': OpenImageIO writes no multi-part EXR");
	ImageSpec spec(info->width, info->height, 3, TypeDesc::FLOAT);
	spec.attribute("oiio:ColorSpace", "Linear");
	spec.attribute("compression", "zip");   // lossless, as the sums must be
	spec.attribute("Software", "eclat " PACKAGE_VERSION);
	spec.attribute("eclat:scene", info->scene ? info->scene : "");
	spec.attribute("eclat:samples", (int)info->samples);
	spec.attribute("eclat:total", (int)info->total);
	spec.attribute("eclat:first", (int)info->first);
	spec.attribute("eclat:count", (int)info->count);
	char region[64];
	std::snprintf(region, sizeof region, "%d %d %d %d", info->region[0], info->region[1], info->region[2],
	              info->region[3]);
	spec.attribute("eclat:region", region);
	spec.attribute("eclat:gamma", info->gamma);
	spec.attribute("eclat:options", info->key.options ? info->key.options : "");
	spec.attribute("eclat:files", info->key.files ? info->key.files : "");

	ImageSpec sums_spec(info->width, info->height, SUM_CHANNELS, TypeDesc::FLOAT);
	sums_spec.channelnames.clear();
	for (int i = 0; i < SUM_CHANNELS; i++)
		sums_spec.channelnames.push_back(sum_channel(i));
	sums_spec.attribute("compression", "zip");
	sums_spec.attribute("name", "eclat.sums");
	spec.attribute("name", "rgb");

	size_t n = (size_t)info->width * info->height;
	std::vector<float> px(n * SUM_CHANNELS);
	for (size_t i = 0; i < n; i++)
		for (int c = 0; c < 4; c++)
			to_chunks(sums[4 * i + c], &px[i * SUM_CHANNELS + 3 * c]);
	char tmp[4200];
	image_temp_path(p.c_str(), tmp, sizeof tmp);
	ImageSpec specs[2] = { spec, sums_spec };
	if (!out->open(tmp, 2, specs))   /* opening may have made tmp before failing to write its header */
		return image_finish(tmp, p.c_str(), out->geterror().c_str(), info->width, info->height, err, errlen);
	bool ok = out->write_image(TypeDesc::FLOAT, rgb) && out->open(tmp, sums_spec, ImageOutput::AppendSubimage) &&
	          out->write_image(TypeDesc::FLOAT, px.data());
	std::string msg = out->geterror();
	ok = out->close() && ok;
	if (!ok && msg.empty())
		msg = out->geterror();
	return image_finish(tmp, p.c_str(), ok ? NULL : msg.c_str(), info->width, info->height, err, errlen);
}

static char *dup_attr(const ImageSpec &spec, const char *name)
{
	return strdup(spec.get_string_attribute(name).c_str());
}

/* EXR keeps channels in alphabetical order: each sum's is found by its name. */
static bool read_info(const ImageSpec &spec, const ImageSpec &sums, split_info *info, int at[SUM_CHANNELS])
{
	const ParamValue *total = spec.find_attribute("eclat:total", TypeDesc::INT);
	if (!total)
		return false;
	for (int i = 0; i < SUM_CHANNELS; i++) {
		at[i] = sums.channelindex(sum_channel(i));
		if (at[i] < 0 || sums.width != spec.width || sums.height != spec.height)
			return false;
	}
	info->width = spec.width;
	info->height = spec.height;
	info->samples = spec.get_int_attribute("eclat:samples");
	info->total = spec.get_int_attribute("eclat:total");
	info->first = spec.get_int_attribute("eclat:first");
	info->count = spec.get_int_attribute("eclat:count");
	info->gamma = spec.get_float_attribute("eclat:gamma");
	std::string r = spec.get_string_attribute("eclat:region");
	if (std::sscanf(r.c_str(), "%d %d %d %d", &info->region[0], &info->region[1], &info->region[2],
	                &info->region[3]) != 4)
		return false;
	info->scene = dup_attr(spec, "eclat:scene");
	info->key.options = dup_attr(spec, "eclat:options");
	info->key.files = dup_attr(spec, "eclat:files");
	return true;
}

extern "C" int split_read_here(const char *path, split_info *info, int64_t **sums, char *err, size_t errlen)
{
	*info = split_info();
	*sums = nullptr;
	/* only OpenEXR looks at it: a part is an EXR, and no other decoder (there
	 * are dozens behind ImageInput::open) should see what another machine sent */
	auto in = ImageInput::create("openexr");
	ImageSpec opened;
	if (!in || !in->valid_file(path) || !in->open(path, opened)) {
		std::string why = in ? in->geterror() : OIIO::geterror();
		return fail(err, errlen, why.empty() ? "not an EXR of eclat's" : why);
	}
	const ImageSpec spec = in->spec();
	int at[SUM_CHANNELS];
	if (!in->seek_subimage(1, 0) || !read_info(spec, in->spec(), info, at)) {
		split_info_free(info);
		return fail(err, errlen, "not an EXR of eclat's with its sums (eclat writes them in every .exr it renders)");
	}
	if (split_size_check(spec.width, spec.height, err, errlen)) {
		split_info_free(info);
		return -1;
	}
	size_t n = (size_t)spec.width * spec.height;
	std::vector<float> px(n * SUM_CHANNELS);
	int64_t *s = (int64_t *)std::malloc(n * 4 * sizeof *s);
	if (!s || !in->read_image(1, 0, 0, SUM_CHANNELS, TypeDesc::FLOAT, px.data())) {
		std::string why = s ? in->geterror() : "out of memory";
		std::free(s);
		split_info_free(info);
		return fail(err, errlen, "cannot read its pixels (truncated?): " + why);
	}
	for (size_t i = 0; i < n; i++)
		for (int c = 0; c < 4; c++) {
			float chunk[3];
			for (int k = 0; k < 3; k++)
				chunk[k] = px[i * SUM_CHANNELS + at[3 * c + k]];
			s[4 * i + c] = from_chunks(chunk);
		}
	*sums = s;
	return 0;
}
