#pragma once
// Checking a PCD binary_compressed body's LZF stream before PCL decompresses it: PCL 1.13 only
// says that its reader rejected the file when the stream is corrupt, so the stream is walked here
// (no output written, constant memory) and the first fault is named with its byte in the file.

#include <cstdint>
#include <filesystem>

namespace octopoint::prepare {

// Walks the `compressed` LZF bytes at file byte `offset` as liblzf's lzf_decompress (which PCL's
// lzfDecompress copies) would, and throws PrepareError "PATH: corrupt: ... (data at byte N)"
// unless they expand to exactly `uncompressed` bytes.
void checkLzfStream(const std::filesystem::path& path, std::uint64_t offset,
                    std::uint64_t compressed, std::uint64_t uncompressed);

}  // namespace octopoint::prepare
