// What tinyobjloader does not check or keep, read from the OBJ and MTL text itself: values
// that are not numbers (it reads them as 0), face indices out of range (it names only the last
// line), skin weights (its reader of them is unsafe), the lines of the o/g statements (for
// messages about a mesh), and the statements each MTL material wrote. Used by obj_importer.cpp.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/log.h"

namespace glint::obj {

// A location in `file` (column 0 when the line is 0: the file as a whole).
FileLoc file_loc(const std::shared_ptr<const std::string>& file, int line, int column = 1);

// tinyobjloader reports lines as "(line 12.)", "... line 12.)" or "line: 12", after any text it
// quotes from the file (a material name may read "line4444..."): the last such number, 0 when
// there is none or it does not fit an int.
int reported_line(const std::string& message);

// The first line of `s` (tinyobjloader's messages run on).
std::string first_line(const std::string& s);

// The line of the k-th (0-based) `cmd` statement (v, vt, vn) of the file, 0 when not found.
int statement_line(const std::string& path, const char* cmd, size_t k);

// `vw` statements (skin weights) mean nothing to glint, which has no skinning, and
// tinyobjloader's reader of them casts joint ids to int unchecked (1e26 or inf is undefined
// behaviour, found by fuzz_obj under UBSan). Each becomes a comment before tinyobjloader reads
// the text, split into lines as tinyobjloader splits them (at \n, \r or \r\n), and the
// first is named in one warning.
void drop_skin_weights(std::string& text, const std::shared_ptr<const std::string>& file,
                       Diagnostics& diag);

// Faces that name normals (`f 1/1/1 ...`) in a file that defines no `vn` at all: the normal
// fields are blanked out (columns kept) and one warning says so, and the faces are shaded
// from their geometry, as other readers (Blender's) do. Some exporters write such files; a
// normal index past the normals a file does define stays an error.
void drop_undefined_normals(std::string& text, const std::shared_ptr<const std::string>& file,
                            Diagnostics& diag);

// The `o` and `g` statements of the file, in order: each one's name (the rest of its line,
// trimmed, as tinyobjloader names the shape it starts) and line, so that what is said about
// a mesh points at the statement that named it.
struct ShapeStatement {
    std::string name;
    int line = 0;
};

std::vector<ShapeStatement> shape_statements(const std::string& text);

// One pass over the OBJ file: the values of every v, vn and vt statement are numbers, enough
// of them (v x y z [w] or v x y z r g b; vn x y z; vt u [v [w]]).
void check_obj_numbers(const std::string& path, const std::shared_ptr<const std::string>& file);

// tinyobjloader only checks face indices against the final counts and names the last line.
// On that error path, find the first face whose index is out of range where it is written
// (OBJ indices are 1-based, negative ones count back from the last element defined so far).
FileLoc locate_bad_index(const std::string& path, const std::shared_ptr<const std::string>& file,
                         std::string* what);

// What the MTL files say beyond tinyobjloader's values: the statements each material wrote
// (lowercased keywords), and whether Blender wrote the file (its first line).
// Also checks that the values tinyobjloader reads as numbers are numbers.
struct MtlStatements {
    std::map<std::string, std::set<std::string>> keywords;  // by material name
    std::map<std::string, std::set<std::string>> gray;      // colors given as one value
    std::set<std::string> blender;                          // materials in Blender's files
};

MtlStatements scan_mtl(const std::vector<std::string>& files);

}  // namespace glint::obj
