#pragma once
// The names of the output files, which the readers check (two names must not give one file)
// and the writers use.
#include <string>
#include <vector>

namespace bemcontact::io {

// The files named after a contact and after an elastic region (the name with every
// character but letters, digits, '-' and '_' written as '_'), per-step files aside, for the reader
// to refuse names whose files would coincide; and the run's own files.
std::vector<std::string> contact_file_names(const std::string& contact);
std::vector<std::string> region_file_names(const std::string& region);
std::vector<std::string> model_file_names();

// The stem of a body's, region's, subdomain's or contact's files (<stem>_boundary.csv): its
// name with characters other than letters, digits, '-' and '_' turned into '_'.
std::string file_stem(const std::string& name);

// What a body's files start with: "<stem>_" for a body the file named ([[body]]: its
// <name>_boundary.csv whichever solver runs it), "" for a one-body file's (boundary.csv).
std::string body_file_prefix(const std::string& name, bool named);

}  // namespace bemcontact::io
