// How far a long experiment has got ("rendering the rgb reference...", "audited ..."): text
// handed to a sink the caller chooses. The command line passes printToStderr; a caller that
// wants silence leaves the sink empty.
#pragma once

#include <functional>
#include <string>

namespace lamina::experiments {

using ProgressSink = std::function<void(const std::string& text)>;

/// Gives `text` to the sink, if there is one.
inline void tell(const ProgressSink& sink, const std::string& text) {
    if (sink) sink(text);
}

/// The command line's sink: the text as it is on stderr.
void printToStderr(const std::string& text);

}  // namespace lamina::experiments
