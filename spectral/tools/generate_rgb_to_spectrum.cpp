// Build-time generator of lamina's RGB -> spectrum coefficient table (Jakob and Hanika 2019,
// section 4.2): for each choice of the largest RGB component l, a res^3 grid over
// (z = that component, x and y = the other two divided by it), with z spaced by a double
// smoothstep to concentrate entries near black and full saturation. Each entry is fitted
// by Gauss-Newton, warm-started from its neighbour along z (the paper's continuation
// strategy, which keeps the iteration in the basin of the smooth solution).
//
// Output: a binary file, "LRGB" magic, int32 resolution, float scale[res],
// float coefficients[3][res(z)][res(y)][res(x)][3] in nm units (c0, c1, c2).
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <thread>
#include <vector>

#include "lamina/spectral/rgb_to_spectrum_fit.h"

namespace {

double smoothstep(double x) {
    return x * x * (3.0 - 2.0 * x);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: generate_rgb_to_spectrum RESOLUTION OUTPUT\n";
        return 2;
    }
    const int res = std::atoi(argv[1]);
    if (res < 4 || res > 256) {
        std::cerr << "resolution must be in [4, 256]\n";
        return 2;
    }
    const lamina::RgbToSpectrumFitter fitter;
    std::vector<float> scale(static_cast<std::size_t>(res));
    for (int k = 0; k < res; ++k)
        scale[std::size_t(k)] = float(smoothstep(smoothstep(double(k) / double(res - 1))));

    const std::size_t count = std::size_t(3) * res * res * res * 3;
    std::vector<float> data(count);
    std::atomic<int> nextRow{0};
    std::atomic<double> worst{0.0};
    const int rows = 3 * res;  // (l, y) pairs, each independent
    auto worker = [&] {
        for (int row; (row = nextRow.fetch_add(1)) < rows;) {
            const int l = row / res, j = row % res;
            for (int i = 0; i < res; ++i) {
                const double x = double(i) / double(res - 1), y = double(j) / double(res - 1);
                const int start = res / 5;
                lamina::NormalizedCoefficients c{0, 0, 0};
                auto solve = [&](int k) {
                    const double z = scale[std::size_t(k)];
                    lamina::Rgb<double> rgb;
                    rgb[l] = z;
                    rgb[(l + 1) % 3] = x * z;
                    rgb[(l + 2) % 3] = y * z;
                    const auto f = fitter.fit(rgb, c);
                    c = f.coefficients;
                    if (z > 0.01) {  // the black corner cannot be reached; it needs no record
                        double w = worst.load();
                        while (f.residual > w && !worst.compare_exchange_weak(w, f.residual)) {
                        }
                    }
                    const auto p = lamina::RgbToSpectrumFitter::toNanometres(c);
                    const std::size_t idx =
                        ((((std::size_t(l) * res + std::size_t(k)) * res + std::size_t(j)) * res) +
                         std::size_t(i)) *
                        3;
                    data[idx] = float(p.c0);
                    data[idx + 1] = float(p.c1);
                    data[idx + 2] = float(p.c2);
                };
                for (int k = start; k < res; ++k)
                    solve(k);
                c = {0, 0, 0};
                for (int k = start; k >= 0; --k)
                    solve(k);
            }
        }
    };
    const unsigned n = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < n; ++t)
        threads.emplace_back(worker);
    for (auto& t : threads)
        t.join();

    const std::string tmp = std::string(argv[2]) + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        const std::int32_t header[2] = {0x4247524c /* "LRGB" */, res};
        out.write(reinterpret_cast<const char*>(header), sizeof header);
        out.write(reinterpret_cast<const char*>(scale.data()),
                  std::streamsize(scale.size() * sizeof(float)));
        out.write(reinterpret_cast<const char*>(data.data()),
                  std::streamsize(data.size() * sizeof(float)));
        if (!out) {
            std::cerr << "cannot write " << tmp << "\n";
            return 1;
        }
    }
    std::rename(tmp.c_str(), argv[2]);
    std::printf("RGB -> spectrum table: %d^3 x 3 entries, worst CIELAB residual %.2e\n", res,
                worst.load());
    return 0;
}
