// `lamina compare` and lamina.compare: the command line measures image files, Python arrays
// (or Images) it already holds.
#include "declarations.h"
#include "lamina/experiments/image_metrics.h"

namespace lamina::experiments {

CommandDecl compareDeclaration() {
    CommandDecl c;
    c.name = "compare";
    c.help = "Error metrics of an image against a reference (relMSE epsilon 1e-2)";
    c.returns = "a dict of mse, rmse, relmse, mae and max, or the one metric named";
    c.options = {
        fileOption("image", "Image to measure (EXR or any OpenImageIO format)")
            .asPositional()
            .asRequired()
            .existing()
            .spelledInPython("a", "Python measures an (H, W, 3) array or an Image, not a file"),
        fileOption("reference", "Reference image")
            .asPositional()
            .asRequired()
            .existing()
            .differsInPython("an (H, W, 3) array or an Image, not a file"),
        nameListOption("metric", "Comma-separated: " + kMetricNames.list(), kMetricNames, "metric")
            .byDefault(kMetricNames.names())
            .differsInPython("one name, whose value is returned; None (the default) returns a "
                             "dict of every metric"),
        textOption("diff",
                   "Write a false-colour map of |image - reference|: NAME.png is a figure, also as "
                   "NAME.pdf (with its data NAME.figure.json, NAME.f32); another format the "
                   "image alone")
            .commandLineOnly("a picture file; in Python |a - b| is one NumPy expression"),
        positiveOption("diff-scale",
                       "The top of --diff's colour scale (default: the difference's 99th "
                       "percentile)")
            .commandLineOnly("the scale of --diff's picture"),
        textOption("html",
                   "Write a self-contained page (NAME.html) with a viewer of the two images: A/B, "
                   "exposure, zoom to pixels, the difference, the relative error, the values "
                   "under the cursor")
            .commandLineOnly("a web page; in Python the arrays are already at hand"),
    };
    return c;
}

}  // namespace lamina::experiments
