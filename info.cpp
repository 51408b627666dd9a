#include "growth/lsystem/lsystem_model.hpp"
#include "growth/lsystem/lsystem_svg.hpp"
#include <iostream>
#include <fstream>
#include <sstream>
#include <filesystem>
int main(){ for (auto& e : std::filesystem::directory_iterator("/work/lsys/assets/lsystems")) {
 std::ifstream in(e.path()); std::stringstream ss; ss << in.rdbuf();
 auto m = arbor::readLsystemModel(ss.str(), e.path().string());
 auto g = arbor::lsystemGraph(*arbor::lsystemOf(m), 1);
 auto s = m.grow({});
 int lv=0; for (auto& st : s.stems) lv = std::max<int>(lv, st.level);
 std::cout << e.path().filename() << " graph " << g.nodes.size() << " leaves " << g.leaves.size() << " skel nodes " << s.nodes.size() << " stems " << s.stems.size() << " maxlevel " << lv << " est " << m.estimate(0).nodes << "\n";
 try { std::ofstream("/tmp/lsq/" + e.path().stem().string() + ".svg") << arbor::lsys::writeLsystemSvg(*arbor::lsystemOf(m)); } catch (std::exception&) {}
}}
