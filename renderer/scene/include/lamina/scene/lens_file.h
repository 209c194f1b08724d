// A realistic camera's lens system (Kolb, Mitchell and Hanrahan 1995, "A Realistic Camera
// Model for Computer Graphics"), read from a lens file as pbrt-v4 reads them: one interface a
// line, from the front (the scene's side) to the rear (the film's), four numbers each --
//
//   curvature radius   thickness   index of refraction   aperture diameter     (mm)
//
// a radius > 0 having its centre of curvature towards the film, 0 the aperture stop (a plane;
// its index 0); the thickness the distance along the axis to the next interface; the index
// that of the glass behind the interface (0 or 1: air). `#` starts a comment. Lengths are
// millimetres and become metres (the scene unit of a realistic camera, as in pbrt-v4).
// Bounds: at most 64 KiB of text, 64 interfaces, lengths below 1e5 mm, indices 0 or in [1, 4],
// at most one stop, and every cap no wider than its sphere; an error is one InputError line
// naming the file and the line.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lamina::render {

/// One interface of a lens system, in metres.
struct LensInterface {
    double curvatureRadius = 0;  ///< > 0: centre towards the film; 0: the aperture stop
    double thickness = 0;        ///< along the axis to the next interface (towards the film)
    double eta = 1;              ///< of the medium behind it (towards the film); 1: air
    double apertureRadius = 0;
    bool isStop() const { return curvatureRadius == 0; }
};

inline constexpr std::size_t kMaxLensFileBytes = 64 * 1024;
inline constexpr std::size_t kMaxLensInterfaces = 64;

/// The interfaces of a lens file's text; `name` names it in errors ("NAME:LINE: ...").
std::vector<LensInterface> parseLensFile(const std::string& text, const std::string& name);
/// The same from a file.
std::vector<LensInterface> readLensFile(const std::filesystem::path& file);

}  // namespace lamina::render
