#pragma once
// What a served file is, by its name's extension: the Content-Type header octopoint-serve sends,
// so that a browser shows a page served beside the models (docs/web.md) and compiles its wasm as
// it streams (WebAssembly.instantiateStreaming accepts only application/wasm).

#include <string_view>

namespace octopoint::net {

// The media type of a file named `name` (the extension is matched without regard to case);
// application/octet-stream for a model and for anything unknown.
std::string_view contentTypeFor(std::string_view name);
// Whether `name` is a page (.html), which gets the Content-Security-Policy below.
bool isPage(std::string_view name);
// The policy a page is sent with: scripts, styles and fetches only from the same server, no inline
// script or style, no eval; 'wasm-unsafe-eval' lets the page compile its WebAssembly.
inline constexpr std::string_view kPagePolicy =
    "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self'; "
    "img-src 'self' data:; object-src 'none'; base-uri 'none'; frame-ancestors 'self'";

}  // namespace octopoint::net
