// What to do about the LIGGGHTS errors a new user meets first. LIGGGHTS's own messages name the
// source line that raised them, not the fix; these hints name the fix.
#ifndef ISPHDEM_LIGGGHTS_ERROR_HINTS_HPP
#define ISPHDEM_LIGGGHTS_ERROR_HINTS_HPP

#include <string>

namespace isphdem {

// A one-sentence hint for a LIGGGHTS ERROR line ("ERROR: ..." or "ERROR on proc N: ..."), or ""
// when none is known.
std::string liggghts_error_hint(const std::string& error_line);

}  // namespace isphdem

#endif
