// image_oiio.cpp: the only file that talks to OpenImageIO.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

#include "image.h"

using namespace OIIO;

static bool is_linear_format(const std::string &path)
{
	std::string ext = Strutil::lower(Filesystem::extension(path));
	return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".pfm";
}

static float srgb_encode(float c)
{
	c = c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
	return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

static int fail(char *err, size_t errlen, const std::string &msg)
{
	std::snprintf(err, errlen, "%s", msg.c_str());
	return -1;
}

extern "C" int image_format_known(const char *path)
{
	auto out = ImageOutput::create(path);
	return out ? 1 : 0;
}

extern "C" int image_write(const char *path, const float *rgb, int width, int height,
                           const image_meta *meta, char *err, size_t errlen)
{
	std::string p(path);
	auto out = ImageOutput::create(p);
	if (!out)
		return fail(err, errlen, "cannot write '" + p + "': no image format for this extension");
	bool linear = is_linear_format(p);
	ImageSpec spec(width, height, 3, linear ? TypeDesc::FLOAT : TypeDesc::UINT8);
	spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
	spec.attribute("Software", "eclat " PACKAGE_VERSION);
	if (meta && meta->scene)
		spec.attribute("eclat:scene", meta->scene);
	if (meta)
		spec.attribute("eclat:samples", (int)meta->samples);

	std::vector<float> pixels(rgb, rgb + (size_t)width * height * 3);
	if (!linear)
		for (float &c : pixels)
			c = srgb_encode(c);

	// The temporary file sits beside the target, so the rename cannot cross file systems.
	std::string dir = Filesystem::parent_path(p);
	std::string tmp = (dir.empty() ? std::string() : dir + "/") + "." +
	                  Filesystem::filename(p) + ".eclat-" + std::to_string(getpid()) + ".tmp";
	if (!out->open(tmp, spec))
		return fail(err, errlen, "cannot write '" + p + "': " + out->geterror());
	bool ok = out->write_image(TypeDesc::FLOAT, pixels.data());
	std::string msg = out->geterror();
	ok = out->close() && ok;
	if (!ok) {
		Filesystem::remove(tmp);
		return fail(err, errlen, "cannot write '" + p + "': " + (msg.empty() ? out->geterror() : msg));
	}
	if (std::rename(tmp.c_str(), p.c_str()) != 0) {
		std::string why = std::strerror(errno);
		Filesystem::remove(tmp);
		return fail(err, errlen, "cannot write '" + p + "': " + why);
	}
	return 0;
}
