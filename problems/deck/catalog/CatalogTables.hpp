// The section catalogue's tables as compiled in: the text of each CSV file under
// problems/deck/catalog/tables/ (one per family), named by its file's stem. CMake writes the
// definition (generated/CatalogTables.cpp) from the files at configure time.
#pragma once

#include <string_view>
#include <vector>

namespace beamrotor {

struct CatalogTable {
  std::string_view family;  ///< e.g. "IPE", the file's stem
  std::string_view csv;     ///< the file's text: '#' comment lines, a header, one row a line
};

const std::vector<CatalogTable>& catalogTables();

}  // namespace beamrotor
