#pragma once
// The files of `bemcontact probe` (docs/probe.md), as strings for OutputDirectory:
//   probe.csv  point,line,distance,x,y,body,on_boundary,u1,u2,s11,s22,s12,s33,von_mises,s1,s2,s3
//              one row per point and body (or region) holding it, in the order asked
//              (a point on an interface has a row for each side, in the order a line
//              crosses it);
//   probe.vtk  the same rows as VTK POLYDATA: each --line a polyline (broken where its
//              points lie outside every body), the points of a points file as vertices;
//              point data u, von_mises, s11..s33, stress, s1, s2, s3, distance, line,
//              on_boundary, body (index into the field data body_names).
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/bem/probe.hpp"
#include "bemcontact/io/output/csv_table.hpp"

namespace bemcontact::io {

struct ProbeRow {
  Index point = 0;        // in the order asked: the points file's, then each --line's
  int line = 0;           // the --line it belongs to (1, 2, ...); 0: a point of the points file
  double distance = 0.0;  // from its line's start (0 for a listed point)
  Vec2 position = Vec2::Zero();
  int body = 0;           // into the body names
  bem::ProbeValue value;
};

// probe.csv as a table (io/output/csv_table.hpp), and as its text.
CsvTable probe_table(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names);
std::string probe_csv(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names);
std::string probe_vtk(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names,
                      std::string_view title);

}  // namespace bemcontact::io
