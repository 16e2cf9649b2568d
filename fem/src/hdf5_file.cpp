// The HDF5 helpers of hdf5_file.h.
#include "hdf5_file.h"

namespace meshprep::detail {

Hdf5Quiet::Hdf5Quiet() {
  H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Hdf5Quiet::~Hdf5Quiet() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }

namespace {

// H5Ewalk2's callback: keeps the description of the last (innermost) entry walked downward.
herr_t keep_innermost(unsigned, const H5E_error2_t* error, void* data) {
  if (error->desc && error->desc[0]) *static_cast<std::string*>(data) = error->desc;
  return 0;
}

}  // namespace

std::string hdf5_reason() {
  std::string description;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keep_innermost, &description);
  // The file drivers quote the system's message: "..., errno = 28, error message = 'No space left
  // on device', ..." (H5FDsec2.c).
  const std::string quote = "error message = '";
  const std::size_t from = description.find(quote);
  if (from != std::string::npos) {
    const std::size_t start = from + quote.size();
    const std::size_t end = description.find('\'', start);
    if (end != std::string::npos) return description.substr(start, end - start);
  }
  return description;
}

}  // namespace meshprep::detail
