// `isphdem dem SCRIPT [liggghts options]`: a drop-in for `liggghts -in SCRIPT [options]` with
// `fix couple/isph` available.
#ifndef ISPHDEM_DEM_COMMAND_HPP
#define ISPHDEM_DEM_COMMAND_HPP

namespace isphdem {

// argv[0] is "dem". Returns the exit status; LIGGGHTS input errors exit the process with 1.
int dem_main(int argc, char** argv);

}  // namespace isphdem

#endif
