// A dataset's chunks shuffled and deflated on the threads, written by
// H5Dwrite_chunk (hdf5_chunk_compression.hpp). Each chunk is what HDF5's
// pipeline would store: the full chunk (the edges padded with the fill
// value, zero), its bytes shuffled (byte k of every element together, the
// shuffle filter's order), then a zlib stream (compress2, as the deflate
// filter makes it); filter mask 0, all filters applied.
#include "hdf5_chunk_compression.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "halfspace/error.hpp"
#include "halfspace/threads.hpp"
#include "hdf5_handle.hpp"

namespace halfspace::io::detail {
#ifndef H5_HAVE_PARALLEL
namespace {

// Chunks compressed per batch: a few per thread keeps the threads busy while
// the batch's buffers stay small beside the dataset.
constexpr std::size_t kChunksPerThread = 4;

struct ChunkWork {
  std::vector<unsigned char> plain, shuffled, packed;
  std::vector<hsize_t> offset;
  uLongf packed_size = 0;
  bool failed = false;
};

// The chunk at `offset` of `data`, padded with zeros, into `plain`: row by
// row (a row runs along the last axis), each row's coordinates from its
// index in the chunk.
void gather_chunk(const unsigned char* data, const std::vector<hsize_t>& dims, const std::vector<hsize_t>& chunk,
                  const std::vector<hsize_t>& offset, std::size_t element_size, std::vector<unsigned char>& plain) {
  const std::size_t last = dims.size() - 1;
  bool partial = false;
  for (std::size_t k = 0; k <= last; ++k) partial = partial || offset[k] + chunk[k] > dims[k];
  if (partial) std::fill(plain.begin(), plain.end(), 0);
  const hsize_t run = std::min(chunk[last], dims[last] - offset[last]);
  std::size_t rows = 1;
  for (std::size_t k = 0; k < last; ++k) rows *= chunk[k];
  for (std::size_t row = 0; row < rows; ++row) {
    bool inside = true;
    std::size_t rest = row, source = offset[last], stride = dims[last];
    for (std::size_t k = last; k-- > 0;) {
      const hsize_t coordinate = offset[k] + rest % chunk[k];
      rest /= chunk[k];
      inside = inside && coordinate < dims[k];
      source += coordinate * stride;
      stride *= dims[k];
    }
    if (inside) {
      std::memcpy(plain.data() + row * chunk[last] * element_size, data + source * element_size, run * element_size);
    }
  }
}

// HDF5's shuffle: byte b of element i to b * count + i.
void shuffle_bytes(const std::vector<unsigned char>& plain, std::size_t element_size,
                   std::vector<unsigned char>& shuffled) {
  const std::size_t count = plain.size() / element_size;
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t b = 0; b < element_size; ++b) shuffled[b * count + i] = plain[i * element_size + b];
  }
}

}  // namespace
#endif

bool write_deflated_chunks(hid_t dataset, std::string_view name, const std::vector<hsize_t>& dims,
                           const std::vector<hsize_t>& chunk, std::size_t element_size, unsigned level,
                           const void* data) {
#ifdef H5_HAVE_PARALLEL
  // H5Dwrite_chunk is not supported by the parallel HDF5.
  (void)dataset, (void)name, (void)dims, (void)chunk, (void)element_size, (void)level, (void)data;
  return false;
#else
  const std::size_t rank = dims.size();
  std::size_t chunk_elements = 1;
  std::vector<hsize_t> per_axis(rank);
  std::size_t chunks = 1;
  for (std::size_t k = 0; k < rank; ++k) {
    chunk_elements *= chunk[k];
    per_axis[k] = (dims[k] + chunk[k] - 1) / chunk[k];
    chunks *= per_axis[k];
  }
  const std::size_t chunk_bytes = chunk_elements * element_size;
  // No more threads and buffers than chunks: a small field on many threads
  // must not allocate a batch it cannot fill.
  const int team = static_cast<int>(std::min<std::size_t>(std::max(1, threads()), chunks));
  std::vector<ChunkWork> work(std::min(static_cast<std::size_t>(team) * kChunksPerThread, chunks));
  for (ChunkWork& w : work) {
    w.plain.resize(chunk_bytes);
    w.shuffled.resize(element_size > 1 ? chunk_bytes : 0);
    w.packed.resize(compressBound(static_cast<uLong>(chunk_bytes)));
    w.offset.resize(rank);
  }
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t first = 0; first < chunks; first += work.size()) {
    const auto batch = static_cast<std::ptrdiff_t>(std::min(work.size(), chunks - first));
#pragma omp parallel for schedule(dynamic, 1) num_threads(team)
    for (std::ptrdiff_t b = 0; b < batch; ++b) {
      ChunkWork& w = work[static_cast<std::size_t>(b)];
      // The chunk's offset from its row-major index.
      std::size_t index = first + static_cast<std::size_t>(b);
      for (std::size_t k = rank; k-- > 0;) {
        w.offset[k] = (index % per_axis[k]) * chunk[k];
        index /= per_axis[k];
      }
      gather_chunk(bytes, dims, chunk, w.offset, element_size, w.plain);
      const std::vector<unsigned char>& filtered = element_size > 1 ? w.shuffled : w.plain;
      if (element_size > 1) shuffle_bytes(w.plain, element_size, w.shuffled);
      w.packed_size = static_cast<uLongf>(w.packed.size());
      w.failed = compress2(w.packed.data(), &w.packed_size, filtered.data(), static_cast<uLong>(chunk_bytes),
                           static_cast<int>(level)) != Z_OK;
    }
    for (std::ptrdiff_t b = 0; b < batch; ++b) {
      const ChunkWork& w = work[static_cast<std::size_t>(b)];
      if (w.failed) throw FileError(fmt::format("could not compress a chunk of dataset '{}' (zlib)", name));
      if (H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, w.offset.data(), w.packed_size, w.packed.data()) < 0) {
        throw FileError(fmt::format("could not write a chunk of dataset '{}': {}", name, error_reason()));
      }
    }
  }
  return true;
#endif
}

}  // namespace halfspace::io::detail
