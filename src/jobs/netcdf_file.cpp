// The NetCDF form of a table dataset (include/viscor/jobs/netcdf_file.hpp).
#include <viscor/jobs/netcdf_file.hpp>

#include <viscor/core/exceptions.hpp>
#include <viscor/jobs/files.hpp>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#if VISCOR_WITH_NETCDF
#include <netcdf.h>
#include <netcdf_mem.h>
#endif

namespace viscor::jobs {

std::string netcdf_path_for(const std::string& table_path) {
  const std::string csv = ".csv";
  if (table_path.size() > csv.size() && table_path.compare(table_path.size() - csv.size(), csv.size(), csv) == 0)
    return table_path.substr(0, table_path.size() - csv.size()) + ".nc";
  return table_path + ".nc";
}

#if VISCOR_WITH_NETCDF

namespace {

void check(int status, const std::string& what) {
  if (status != NC_NOERR) throw error("writing NetCDF: " + what + ": " + nc_strerror(status));
}

// The file being written in memory; closed (and its memory freed) on every path.
class memory_file {
 public:
  memory_file() { check(nc_create_mem("viscor-table.nc", NC_NETCDF4 | NC_CLOBBER, 1 << 16, &m_id), "create"); }
  memory_file(const memory_file&) = delete;
  memory_file& operator=(const memory_file&) = delete;
  ~memory_file() {
    if (m_open) {
      NC_memio io{};
      if (nc_close_memio(m_id, &io) == NC_NOERR) std::free(io.memory);
    }
  }
  int id() const { return m_id; }
  /// Closes the file and returns its bytes.
  std::string close() {
    NC_memio io{};
    m_open = false;
    check(nc_close_memio(m_id, &io), "close");
    std::string bytes(static_cast<const char*>(io.memory), io.size);
    std::free(io.memory);
    return bytes;
  }

 private:
  int m_id = -1;
  bool m_open = true;
};

void put_text_attribute(int file, int variable, const std::string& name, const std::string& value) {
  check(nc_put_att_text(file, variable, name.c_str(), value.size(), value.c_str()), "attribute " + name);
}

// Defines one array (its dimensions already defined) with its attributes; returns its id.
int define(int file, const dataset_array& a, const std::vector<std::pair<std::string, int>>& dimension_ids,
           const std::string& coordinates) {
  std::vector<int> dims;
  for (const std::string& name : a.dims)
    for (const auto& [dim, id] : dimension_ids)
      if (dim == name) dims.push_back(id);
  const nc_type type = a.kind == dataset_array::type::float64 ? NC_DOUBLE
                       : a.kind == dataset_array::type::int32 ? NC_INT
                                                               : NC_STRING;
  int id = -1;
  check(nc_def_var(file, a.name.c_str(), type, static_cast<int>(dims.size()), dims.data(), &id), "variable " + a.name);
  for (const auto& [name, value] : a.attributes) put_text_attribute(file, id, name, value);
  // xarray (CF): the non-index coordinates a data variable is given with.
  if (!coordinates.empty()) put_text_attribute(file, id, "coordinates", coordinates);
  return id;
}

void put(int file, int id, const dataset_array& a) {
  switch (a.kind) {
    case dataset_array::type::float64: check(nc_put_var_double(file, id, a.numbers.data()), a.name); break;
    case dataset_array::type::int32: check(nc_put_var_int(file, id, a.integers.data()), a.name); break;
    case dataset_array::type::text: {
      std::vector<const char*> texts;
      for (const std::string& t : a.texts) texts.push_back(t.c_str());
      check(nc_put_var_string(file, id, texts.data()), a.name);
      break;
    }
  }
}

}  // namespace

bool netcdf_available() { return true; }

std::string netcdf_file_bytes(const table_dataset& d) {
  memory_file file;
  const int f = file.id();
  std::vector<std::pair<std::string, int>> dimension_ids;
  for (const auto& [name, size] : d.dimensions) {
    int id = -1;
    check(nc_def_dim(f, name.c_str(), size, &id), "dimension " + name);
    dimension_ids.emplace_back(name, id);
  }
  std::string coordinates;  // every coordinate that is not a dimension's own
  for (const dataset_array& c : d.coordinates)
    if (c.dims.size() != 1 || c.dims[0] != c.name) coordinates += (coordinates.empty() ? "" : " ") + c.name;
  std::vector<std::pair<int, const dataset_array*>> arrays;
  for (const dataset_array& c : d.coordinates) arrays.emplace_back(define(f, c, dimension_ids, ""), &c);
  for (const dataset_array& v : d.variables) arrays.emplace_back(define(f, v, dimension_ids, coordinates), &v);
  for (const auto& [name, value] : d.attributes) {
    if (const auto* text = std::get_if<std::string>(&value)) {
      put_text_attribute(f, NC_GLOBAL, name, *text);
    } else {
      const long long number = std::get<std::int64_t>(value);
      check(nc_put_att_longlong(f, NC_GLOBAL, name.c_str(), NC_INT64, 1, &number), "attribute " + name);
    }
  }
  check(nc_enddef(f), "end of definitions");
  for (const auto& [id, a] : arrays) put(f, id, *a);
  return file.close();
}

#else

bool netcdf_available() { return false; }

std::string netcdf_file_bytes(const table_dataset&) {
  require_netcdf();
  return {};
}

#endif

void write_table_netcdf(const std::string& table_path, const std::string& output) {
  require_netcdf();
  if (std::filesystem::weakly_canonical(table_path) == std::filesystem::weakly_canonical(output))
    throw invalid_parameter("the NetCDF output '" + output + "' is the table itself: give another -o");
  write_atomically(output, netcdf_file_bytes(read_table_dataset(table_path)));
}

void require_netcdf() {
  if (!netcdf_available())
    throw error("this build of viscor writes no NetCDF: libnetcdf (Debian: libnetcdf-dev) was not found when it was "
                "configured");
}

}  // namespace viscor::jobs
