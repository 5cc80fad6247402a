// The NetCDF form of a table dataset (jobs/table_dataset.hpp): `viscor table --format
// netcdf` and Python's table(..., format="netcdf"). Written with libnetcdf (Debian:
// libnetcdf-dev) as NetCDF-4, in memory, so that it is published with the table's
// other outputs (jobs/files.hpp write_together). Defined in src/jobs/netcdf_file.cpp.
#pragma once

#include <viscor/jobs/table_dataset.hpp>

#include <string>

namespace viscor::jobs {

/// Whether this build writes NetCDF (libnetcdf was found when it was configured).
bool netcdf_available();
/// Throws viscor::error, saying why, in a build that writes no NetCDF.
void require_netcdf();

/// The bytes of a NetCDF-4 file holding `d`: xarray.open_dataset reads it back as
/// Table.to_xarray() builds it. Throws viscor::error in a build without libnetcdf.
std::string netcdf_file_bytes(const table_dataset& d);

/// Writes the NetCDF form of the table file `table_path` (its sidecar beside it, both
/// read and checked) to `output`, as every output is written (jobs/files.hpp).
void write_table_netcdf(const std::string& table_path, const std::string& output);

/// Where the NetCDF form of a table goes: NAME.csv -> NAME.nc, any other name + ".nc".
std::string netcdf_path_for(const std::string& table_path);

}  // namespace viscor::jobs
