#include "arrays.h"

#include "meshprep/core/errors.h"
#include "meshprep/fem/tet_boundary.h"

#include <cmath>
#include <limits>

namespace meshprep::python {
namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// A numpy array as given; a list or tuple becomes one (of `list_dtype`); anything else is refused.
py::array as_array(const py::handle& value, const std::string& what, const char* list_dtype) {
  if (py::isinstance<py::array>(value)) return py::reinterpret_borrow<py::array>(value);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    try {
      return py::module_::import("numpy").attr("asarray")(value, list_dtype);
    } catch (const py::error_already_set& e) {
      throw InvalidInput(what + ": cannot be read as an array of " + list_dtype + " (" + e.what() + ")");
    }
  }
  throw InvalidInput(what + ": expected a numpy array, not " + std::string(py::str(value.get_type().attr("__name__"))));
}

// An (n, columns) C-contiguous array with n >= 1.
void check_layout(const py::array& a, py::ssize_t columns, const std::string& what) {
  if (a.ndim() != 2 || a.shape(1) != columns)
    throw InvalidInput(what + ": expected shape (n, " + std::to_string(columns) + "), not " + shape_text(a));
  if (a.shape(0) == 0) throw InvalidInput(what + ": empty (shape " + shape_text(a) + ")");
  if (!(a.flags() & py::array::c_style))
    throw InvalidInput(what + ": not C-contiguous (a slice or a transpose); pass numpy.ascontiguousarray(" + what + ")");
}

// (n, K) indices of any integer dtype, each in [0, points).
template <std::size_t K>
std::vector<std::array<std::uint32_t, K>> index_rows(const py::handle& value, std::size_t points, const std::string& what) {
  const py::array a = as_array(value, what, "int64");
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw InvalidInput(what + ": expected an integer dtype, not " + std::string(py::str(a.dtype())));
  check_layout(a, static_cast<py::ssize_t>(K), what);
  // One conversion to int64, whatever the integer dtype (a copy only when it is not int64 already).
  const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  const std::int64_t* data = indices.data();
  std::vector<std::array<std::uint32_t, K>> rows(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t k = 0; k < K; ++k) {
      const std::int64_t index = data[r * K + k];
      if (index < 0 || static_cast<std::uint64_t>(index) >= points)
        throw InvalidInput(what + ": row " + std::to_string(r) + " has index " + std::to_string(index) +
                           ", outside [0, " + std::to_string(points) + ") (the points' rows)");
      rows[r][k] = static_cast<std::uint32_t>(index);
    }
  return rows;
}

// One tag per row, integers >= 1 (0 and negative tags are the writers' "none").
std::vector<int> tags_from_array(const py::handle& value, std::size_t rows, const std::string& what) {
  const py::array a = as_array(value, what, "int64");
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw InvalidInput(what + ": expected an integer dtype, not " + std::string(py::str(a.dtype())));
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != rows)
    throw InvalidInput(what + ": expected shape (" + std::to_string(rows) + ",), one per face, not " + shape_text(a));
  const auto tags = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<int> out(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    const std::int64_t tag = tags.data()[i];
    if (tag < 1 || tag > std::numeric_limits<int>::max())
      throw InvalidInput(what + ": entry " + std::to_string(i) + " is " + std::to_string(tag) + "; tags are integers >= 1");
    out[i] = static_cast<int>(tag);
  }
  return out;
}

TagNames names_from_dict(const py::handle& value, const std::string& what) {
  TagNames names;
  if (value.is_none()) return names;
  if (!py::isinstance<py::dict>(value)) throw InvalidInput(what + ": expected a dict {tag: name}");
  for (const auto& [tag, name] : py::reinterpret_borrow<py::dict>(value)) {
    if (!py::isinstance<py::int_>(tag) || !py::isinstance<py::str>(name))
      throw InvalidInput(what + ": expected int tags and str names");
    names[tag.cast<int>()] = name.cast<std::string>();
  }
  return names;
}

py::array read_only(py::array array) {
  array.attr("flags").attr("writeable") = false;
  return array;
}

}  // namespace

std::vector<Vec3> points_from_array(const py::handle& value, const std::string& what) {
  const py::array a = as_array(value, what, "float64");
  if (!a.dtype().is(py::dtype::of<double>()))
    throw InvalidInput(what + ": expected dtype float64, not " + std::string(py::str(a.dtype())) +
                       " (convert with " + what + ".astype(numpy.float64))");
  check_layout(a, 3, what);
  const double* data = static_cast<const double*>(a.data());
  std::vector<Vec3> points(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
    if (!points[i].allFinite())
      throw InvalidInput(what + ": row " + std::to_string(i) + " is not finite (NaN or infinity)");
  }
  return points;
}

Surface surface_from_arrays(const py::handle& points, const py::handle& faces, const py::handle& patches,
                            const py::handle& patch_names) {
  auto soup = std::make_shared<TriangleSoup>();
  soup->points = points_from_array(points, "points");
  soup->triangles = index_rows<3>(faces, soup->points.size(), "faces");
  if (!patches.is_none()) soup->patches = tags_from_array(patches, soup->triangles.size(), "patches");
  soup->patch_names = names_from_dict(patch_names, "patch_names");
  return {soup};
}

Tets tets_from_arrays(const py::handle& points, const py::handle& tets, const py::handle& boundary_faces,
                      const py::handle& patches, const py::handle& patch_names) {
  auto mesh = std::make_shared<TetMesh>();
  mesh->points = points_from_array(points, "points");
  mesh->tets = index_rows<4>(tets, mesh->points.size(), "tets");
  mesh->tet_regions.assign(mesh->tets.size(), 1);
  if (boundary_faces.is_none()) {
    if (!patches.is_none()) throw InvalidInput("patches: given without boundary_faces (one tag per boundary face)");
    mesh->boundary_faces = tet_boundary(*mesh);
  } else {
    mesh->boundary_faces = index_rows<3>(boundary_faces, mesh->points.size(), "boundary_faces");
  }
  mesh->boundary_tags = patches.is_none() ? std::vector<int>(mesh->boundary_faces.size(), 1)
                                          : tags_from_array(patches, mesh->boundary_faces.size(), "patches");
  mesh->boundary_names = names_from_dict(patch_names, "patch_names");
  return {mesh};
}

py::array points_view(const std::vector<Vec3>& points, const py::handle& owner) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
  return read_only(py::array_t<double>({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}},
                                               points.empty() ? nullptr : points.front().data(), owner));
}

template <std::size_t K>
py::array index_view(const std::vector<std::array<std::uint32_t, K>>& rows, const py::handle& owner) {
  return read_only(py::array_t<std::uint32_t>(
      {static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(K)}, rows.empty() ? nullptr : rows.front().data(),
      owner));
}
template py::array index_view<3>(const std::vector<std::array<std::uint32_t, 3>>&, const py::handle&);
template py::array index_view<4>(const std::vector<std::array<std::uint32_t, 4>>&, const py::handle&);

py::array tags_view(const std::vector<int>& tags, const py::handle& owner) {
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(tags.size())};
  return read_only(py::array_t<int>(shape, tags.data(), owner));
}

py::dict names_dict(const TagNames& names) {
  py::dict dict;
  for (const auto& [tag, name] : names) dict[py::int_(tag)] = name;
  return dict;
}

}  // namespace meshprep::python
