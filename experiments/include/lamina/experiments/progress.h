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

/// A text that starts with '\r' replaces the line in progress on a terminal. Without a final
/// newline it is a transient status ("path: batch 3/16") that the next text replaces.

/// The command line's sink: the text as it is on stderr when stderr is a terminal. Otherwise
/// (a log file, a pipe) no carriage return is written: a transient status is left out and a
/// final line is written without its '\r'.
void printToStderr(const std::string& text);

}  // namespace lamina::experiments
