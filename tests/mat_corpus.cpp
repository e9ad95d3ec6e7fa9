// Writes the MAT files of tests/bad_inputs/ (`hystbench_mat_corpus DIR`):
// good files in v5, v7 and v7.3, the struct layouts of dSPACE ControlDesk
// and Simulink, and one file per mistake the reader must name. Kept so that
// the binary files in the corpus can be made again and read as source.
#include <matio.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

using Values = std::vector<double>;
const Values kT{0, 0.001, 0.002, 0.003, 0.004};
const Values kU{0, 1, 2, 1, 0};
const Values kY{0, 0.5, 1.5, 1, 0.25};

matvar_t* vector_var(const char* name, const Values& v, bool row = false) {
  std::size_t dims[2] = {row ? 1 : v.size(), row ? v.size() : 1};
  return Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(v.data()), 0);
}

matvar_t* text_var(const char* name, const std::string& s) {
  std::size_t dims[2] = {1, s.size()};
  return Mat_VarCreate(name, MAT_C_CHAR, MAT_T_UINT8, 2, dims, const_cast<char*>(s.data()), 0);
}

void write(const std::string& path, std::vector<matvar_t*> vars, mat_ft version = MAT_FT_MAT5,
           matio_compression compression = MAT_COMPRESSION_NONE) {
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, version);
  for (matvar_t* v : vars) {
    Mat_VarWrite(mat, v, compression);
    Mat_VarFree(v);
  }
  Mat_Close(mat);
}

std::vector<matvar_t*> good() { return {vector_var("t", kT), vector_var("u", kU), vector_var("y", kY)}; }

// rec.X.Data: time; rec.Y(k).Data and .Name: the signals, as ControlDesk
// exports a recording.
matvar_t* controldesk_record() {
  const char* x_fields[] = {"Name", "Data", nullptr};
  std::size_t one[2] = {1, 1};
  matvar_t* x = Mat_VarCreateStruct2("X", 2, one, x_fields);
  Mat_VarSetStructFieldByName(x, "Name", 0, text_var("Name", "Time"));
  Mat_VarSetStructFieldByName(x, "Data", 0, vector_var("Data", kT, true));
  const char* y_fields[] = {"Name", "Data", nullptr};
  std::size_t two[2] = {1, 2};
  matvar_t* y = Mat_VarCreateStruct2("Y", 2, two, y_fields);
  Mat_VarSetStructFieldByName(y, "Name", 0, text_var("Name", "Model Root/u_V"));
  Mat_VarSetStructFieldByName(y, "Data", 0, vector_var("Data", kU, true));
  Mat_VarSetStructFieldByName(y, "Name", 1, text_var("Name", "Model Root/y_um"));
  Mat_VarSetStructFieldByName(y, "Data", 1, vector_var("Data", kY, true));
  const char* rec_fields[] = {"X", "Y", nullptr};
  matvar_t* rec = Mat_VarCreateStruct2("rec", 2, one, rec_fields);
  Mat_VarSetStructFieldByName(rec, "X", 0, x);
  Mat_VarSetStructFieldByName(rec, "Y", 0, y);
  return rec;
}

// yout.time and yout.signals(k).values: Simulink's "structure with time".
matvar_t* simulink_structure() {
  std::size_t one[2] = {1, 1};
  const char* signal_fields[] = {"values", "label", nullptr};
  std::size_t two[2] = {1, 2};
  matvar_t* signals = Mat_VarCreateStruct2("signals", 2, two, signal_fields);
  Mat_VarSetStructFieldByName(signals, "values", 0, vector_var("values", kU));
  Mat_VarSetStructFieldByName(signals, "label", 0, text_var("label", "u"));
  Mat_VarSetStructFieldByName(signals, "values", 1, vector_var("values", kY));
  Mat_VarSetStructFieldByName(signals, "label", 1, text_var("label", "y"));
  const char* fields[] = {"time", "signals", nullptr};
  matvar_t* yout = Mat_VarCreateStruct2("yout", 2, one, fields);
  Mat_VarSetStructFieldByName(yout, "time", 0, vector_var("time", kT));
  Mat_VarSetStructFieldByName(yout, "signals", 0, signals);
  return yout;
}

matvar_t* segment_cells() {
  std::size_t dims[2] = {kT.size(), 1};
  matvar_t* cell = Mat_VarCreate("segment", MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0);
  for (std::size_t i = 0; i < kT.size(); ++i)
    Mat_VarSetCell(cell, int(i), text_var(nullptr, i < 3 ? "sine" : "steps"));
  return cell;
}

matvar_t* complex_y() {
  Values im(kY.size(), 0.5);
  mat_complex_split_t split{const_cast<double*>(kY.data()), im.data()};
  std::size_t dims[2] = {kY.size(), 1};
  return Mat_VarCreate("y", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &split, MAT_F_COMPLEX);
}

matvar_t* matrix_u() {
  Values both = kU;
  both.insert(both.end(), kU.begin(), kU.end());
  std::size_t dims[2] = {kU.size(), 2};
  return Mat_VarCreate("u", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, both.data(), 0);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: hystbench_mat_corpus DIR\n");
    return 2;
  }
  const std::string dir = std::string(argv[1]) + "/";
  write(dir + "good_v5.mat", good());
  write(dir + "good_v7.mat", good(), MAT_FT_MAT5, MAT_COMPRESSION_ZLIB);
  write(dir + "good_v73.mat", good(), MAT_FT_MAT73);
  auto with_segment = good();
  with_segment.push_back(segment_cells());
  // Uncompressed: matio 1.5.23 cannot read back the cell and struct arrays it
  // compresses itself (those MATLAB or SciPy compress read fine).
  write(dir + "segment_cells.mat", with_segment);
  write(dir + "controldesk_record.mat", {controldesk_record()});
  write(dir + "simulink_structure.mat", {simulink_structure()}, MAT_FT_MAT73);
  write(dir + "mat_missing_u.mat", {vector_var("t", kT), vector_var("y", kY)});
  write(dir + "mat_matrix_u.mat", {vector_var("t", kT), matrix_u(), vector_var("y", kY)});
  write(dir + "mat_complex_y.mat", {vector_var("t", kT), vector_var("u", kU), complex_y()});
  Values nan_y = kY;
  nan_y[2] = std::nan("");
  write(dir + "mat_nan_y.mat", {vector_var("t", kT), vector_var("u", kU), vector_var("y", nan_y)},
        MAT_FT_MAT73);
  write(dir + "mat_short_u.mat",
        {vector_var("t", kT), vector_var("u", Values(kU.begin(), kU.end() - 1)), vector_var("y", kY)});
  write(dir + "mat_text_u.mat", {vector_var("t", kT), text_var("u", "volts"), vector_var("y", kY)});
  write(dir + "mat_struct_u.mat", {vector_var("t", kT), controldesk_record(), vector_var("y", kY)});
  std::ofstream(dir + "not_a_mat.mat") << "t,u,y\n0,0,0\n0.001,1,0.5\n";
  return 0;
}
