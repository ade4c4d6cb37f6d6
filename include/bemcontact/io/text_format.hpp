#pragma once
// Numbers and text fields as the output files write them, shared by the readers' messages
// and the writers (io/input, io/output).
#include <string>
#include <string_view>

namespace bemcontact::io {

// Shortest text that reads back as exactly the same double ("0.1", "1e-05", "100000").
std::string format_number(double value);

// A text field of a CSV file as RFC 4180 writes it: in double quotes (doubled inside) when
// it holds a comma, a quote, a line break or leading or trailing space, or reads as a
// number (so that a name like "nan" is never taken for one); as it is otherwise.
std::string csv_field(std::string_view text);

}  // namespace bemcontact::io
