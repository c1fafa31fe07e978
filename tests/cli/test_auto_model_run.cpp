// coupling.model = "auto" on the seed's reduced erosion layer at dx = 1 mm: without being told,
// it must reproduce the seed's semi-resolved choice (clumps by PMS, fines unresolved), say so
// per grain class, and mark every atom in /dem/model.
#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace isphdem::cli {
namespace {

TEST(AutoModelRun, ReducedErosionLayerResolvesTheClumpsOnly) {
  const auto dir = scratch("auto_model");
  const std::string c = reduced_case();
  const Result r = run(c + " --out " + (dir / "out").string() +
                       " --set coupling.model=auto --set time.end=0.0002"
                       " --set output.interval=0.0001");
  std::printf("%s", r.output.c_str());
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("coupling.model = \"auto\" -> \"semi-resolved\""), std::string::npos);
  EXPECT_NE(r.output.find("clumps d = 5 mm, d/dx 5 -> resolved (PMS), 6 bodies"),
            std::string::npos);
  EXPECT_NE(r.output.find("free spheres d = 1 mm, d/dx 1 -> unresolved"), std::string::npos);
  // The case as run records the model auto chose.
  std::ifstream used(dir / "out" / "case_used.toml");
  const std::string text((std::istreambuf_iterator<char>(used)), {});
  EXPECT_NE(text.find("model = 'semi-resolved'"), std::string::npos);

  if (run_shell("/usr/bin/python3 -c 'import h5py, numpy'").exit_code != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks h5py";
  const Result m = run_shell("/usr/bin/python3 -c \"import h5py, numpy as np; f = h5py.File('" +
                             (dir / "out" / "snap_00000002.h5").string() +
                             "'); m = f['dem/model'][:]; b = f['dem/body'][:]; "
                             "print('clumps', sorted(set(m[b >= 0].tolist())), 'fines', "
                             "sorted(set(m[b < 0].tolist())))\"");
  std::printf("%s", m.output.c_str());
  EXPECT_NE(m.output.find("clumps [1] fines [0]"), std::string::npos);
  // ParaView sees it as a point attribute of the grains.
  std::ifstream xdmf(dir / "out" / "dem.xdmf");
  const std::string x((std::istreambuf_iterator<char>(xdmf)), {});
  EXPECT_NE(x.find("Name=\"model\""), std::string::npos);
}

}  // namespace
}  // namespace isphdem::cli
