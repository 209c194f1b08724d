#!/usr/bin/env python3
"""lamina's efficiency against a given pbrt-v4 render of the same pbrt-v4 scene file.

A benchmark, not a test (never run in CI). pbrt-v4 is not packaged, so the script does not run
it: it takes pbrt-v4's image, the samples per pixel and the seconds it took, and a converged
reference of the scene (for Veach's MIS scene all three are in ../shared/data/peers/veach-mis/,
see its README). It renders the scene with lamina (read through lamina's pbrt-v4 importer) for
each time budget of --times (or each sample count of --spp), and prints per renderer:

  - the MSE against the reference, net of the reference's own noise (peer_efficiency.py: from
    two independent halves given as --reference H1 H2, or, for one reference rendered by lamina
    itself, from --reference-spp N); pbrt-v4's image is independent of either reference;
  - the per-sample variance (MSE x spp) and the sample rate (spp / s) separately, and their
    quotient, the efficiency 1 / (MSE x s); the ratio lamina / pbrt-v4 of each;
  - the image means, relative to the reference's and to each other's (the renderers render the
    same scene when they agree: a difference in the means is a bias, which the MSE counts too).

  python3 benchmarks/peers/pbrt.py ../shared/data/peers/veach-mis/scene-v4.pbrt \\
      --pbrt-image ../shared/data/peers/veach-mis/pbrt-v4_512spp_seed7.exr \\
      --pbrt-spp 512 --pbrt-seconds 52 \\
      --reference ../shared/data/peers/veach-mis/lamina_spectral_8192spp_seed99.exr \\
      --reference-spp 8192 --mode spectral --times 20 --python build/python

Times are wall seconds: pbrt-v4's as given (measure it with `time pbrt --nthreads 2 ...`),
lamina's the render time it prints (BVH and sampling, not the process start-up), both with two
threads. Run both on a quiet machine of the same class.
"""

import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_efficiency as pe  # noqa: E402  (running lamina, image errors, efficiency arithmetic)


def reference_mse(image, references, own_spp=None, reference_spp=None):
    """The image's MSE net of the reference's noise, and the reference's variance. With two
    halves: from their difference. With one reference of lamina's own (own_spp: the image's
    samples, an image rendered by lamina): from the model MSE = v / n + v / N. With one
    reference of a different renderer's image: the reference's variance `reference_variance`
    must be known (None: the raw MSE, with the reference's noise counted against the image)."""
    if len(references) == 2:
        return pe.mse_against_halves(image, references[0], references[1])
    raw = pe.mse(image, references[0])
    if own_spp is not None and reference_spp:
        v, var_ref = pe.own_reference_variance(raw, own_spp, reference_spp)
        return v / own_spp, var_ref
    return raw, 0.0


def measure(lamina_images, pbrt_image, pbrt_spp, pbrt_seconds, references, reference_spp=None):
    """lamina_images: [(image array, spp, seconds)]. Returns the rows to print: per lamina
    image, the two Measurements and their ratios, plus the means."""
    reference_mean = sum(r for r in references) / len(references)
    rows = []
    for image, spp, seconds in lamina_images:
        lamina_mse, var_ref = reference_mse(image, references, spp, reference_spp)
        if len(references) == 2:
            pbrt_mse = pe.mse_against_halves(pbrt_image, references[0], references[1])[0]
        else:
            pbrt_mse = pe.mse(pbrt_image, references[0]) - var_ref
        lamina = pe.Measurement("lamina", spp, seconds, lamina_mse)
        pbrt = pe.Measurement("pbrt-v4", pbrt_spp, pbrt_seconds, pbrt_mse)
        rows.append({
            "lamina": lamina, "pbrt": pbrt, "ratios": pe.ratios(lamina, pbrt),
            "reference_variance": var_ref,
            "lamina_vs_reference": pe.relative_mean_difference(image, reference_mean),
            "pbrt_vs_reference": pe.relative_mean_difference(pbrt_image, reference_mean),
            "lamina_vs_pbrt": pe.relative_mean_difference(image, pbrt_image),
        })
    return rows


def print_rows(rows):
    print("| lamina spp | lamina s | lamina MSE | pbrt-v4 MSE | per-sample variance lamina / "
          "pbrt-v4 | sample rate lamina / pbrt-v4 | efficiency lamina / pbrt-v4 | mean lamina / "
          "pbrt-v4 - 1 | mean lamina / reference - 1 | mean pbrt-v4 / reference - 1 |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        lamina, pbrt, q = r["lamina"], r["pbrt"], r["ratios"]
        print(f"| {lamina.spp} | {lamina.seconds:.2f} | {lamina.mse:.4g} | {pbrt.mse:.4g} | "
              f"{1 / q['variance']:.3f} | {q['rate']:.3f} | {q['efficiency']:.3f}x | "
              f"{100 * r['lamina_vs_pbrt']:+.2f}% | {100 * r['lamina_vs_reference']:+.2f}% | "
              f"{100 * r['pbrt_vs_reference']:+.2f}% |")
    for r in rows:
        if not r["lamina"].mse > 0 or not r["pbrt"].mse > 0:
            print("a net MSE is not positive: the reference is as noisy as the image (render a "
                  "longer reference)")
    if rows:
        print(f"pbrt-v4: {rows[0]['pbrt'].spp} spp in {rows[0]['pbrt'].seconds:g} s, "
              f"{rows[0]['pbrt'].sample_rate:.3g} spp/s, per-sample variance "
              f"{rows[0]['pbrt'].per_sample_variance:.4g}; reference variance taken out "
              f"{rows[0]['reference_variance']:.3g}")
        effs = [r["ratios"]["efficiency"] for r in rows if r["ratios"]["efficiency"] > 0]
        if effs:
            print(f"efficiency ratio lamina / pbrt-v4, geometric mean over {len(effs)} renders: "
                  f"{pe.geometric_mean(effs):.2f}x")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene", help="the pbrt-v4 scene file that both renderers rendered")
    parser.add_argument("--pbrt-image", required=True, help="pbrt-v4's EXR")
    parser.add_argument("--pbrt-spp", type=int, required=True)
    parser.add_argument("--pbrt-seconds", type=float, required=True,
                        help="pbrt-v4's wall time for that image")
    parser.add_argument("--reference", nargs="+", required=True,
                        help="a converged reference, or two independent halves of one")
    parser.add_argument("--reference-spp", type=int,
                        help="one reference rendered by lamina in the same mode: its spp, to take "
                             "its noise out (without it, and without halves, it is not)")
    parser.add_argument("--lamina", default="build/app/lamina")
    parser.add_argument("--python", default="build/python", help="lamina's Python module")
    parser.add_argument("--mode", choices=["rgb", "spectral"], default="spectral",
                        help="pbrt-v4 renders spectrally")
    budget = parser.add_mutually_exclusive_group()
    budget.add_argument("--times", type=float, nargs="+",
                        help="lamina's wall-time budgets in seconds (default: 20)")
    budget.add_argument("--spp", type=int, nargs="+",
                        help="lamina's sample counts instead: a Sobol sampler stratifies best at "
                             "powers of two, where a time budget seldom ends")
    parser.add_argument("--samplers", nargs="+", metavar="SAMPLER",
                        help="render every budget with each of these lamina samplers "
                             "(`--sampler`), interleaved so that they share the machine's "
                             "conditions, and print one table per sampler (default: the "
                             "scene's, which the importer makes sobol-global for pbrt's sobol)")
    parser.add_argument("--seed", type=int, default=5, help="lamina's first seed (one per budget)")
    parser.add_argument("--lamina-args", nargs=argparse.REMAINDER, default=[],
                        help="further `lamina render` options (last on the line)")
    parser.add_argument("--keep", help="directory to keep lamina's images in")
    args = parser.parse_args()
    if len(args.reference) > 2:
        parser.error("--reference takes one image or two halves")
    try:
        print(f"at the start, {pe.load_note()}")
        work = args.keep or tempfile.mkdtemp(prefix="lamina-pbrt-peer-")
        os.makedirs(work, exist_ok=True)
        references = [pe.read_rgb(r, args.python) for r in args.reference]
        pbrt_image = pe.read_rgb(args.pbrt_image, args.python)
        samplers = args.samplers or [None]
        images = {sampler: [] for sampler in samplers}
        budgets = [("spp", n) for n in args.spp] if args.spp else [
            ("seconds", t) for t in (args.times or [20.0])]
        for i, (kind, budget) in enumerate(budgets):
            for sampler in samplers:
                extra = (["--sampler", sampler] if sampler else []) + args.lamina_args
                name = f"lamina-{sampler or 'scene'}-{budget:g}{kind}-{i}.exr"
                out, spp, seconds = pe.run_lamina(
                    args.lamina, args.scene, os.path.join(work, name), seed=args.seed + i,
                    mode=args.mode, extra=extra, **{kind: budget})
                images[sampler].append((pe.read_rgb(out, args.python), spp, seconds))
        own = args.reference_spp if len(args.reference) == 1 else None
        for sampler in samplers:
            if sampler:
                print(f"\nlamina's sampler: {sampler}")
            print_rows(measure(images[sampler], pbrt_image, args.pbrt_spp, args.pbrt_seconds,
                               references, own))
        print(f"at the end, {pe.load_note()}")
    except pe.PeerError as e:
        sys.exit(f"pbrt.py: {e}")


if __name__ == "__main__":
    main()
