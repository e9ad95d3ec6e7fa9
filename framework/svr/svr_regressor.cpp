#include "framework/svr/svr_regressor.hpp"

#include <svm.h>

#include <cmath>
#include <cstdlib>
#include <mutex>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"

namespace hystbench {

// The model as libsvm's svm_predict reads it, pointing into storage owned
// here: dense support vectors (indices 1..d, then -1), coefficients, rho.
struct SvrRegressor::Model {
  SvrHyperparameters hyper;
  int dim = 0;
  std::vector<svm_node> nodes;  // (dim + 1) per support vector
  std::vector<double> coef;
  double rho = 0.0;
  std::vector<svm_node*> rows;
  double* coef_rows[1] = {nullptr};
  svm_model view{};

  // Points `view` at the storage; after every copy or fill. Rows end at
  // their index -1 terminator (libsvm's rows may leave zeros out).
  void link() {
    rows.clear();
    std::size_t start = 0;
    for (std::size_t i = 0; i < coef.size(); ++i) {
      rows.push_back(nodes.data() + start);
      while (nodes[start].index != -1) ++start;
      ++start;
    }
    coef_rows[0] = coef.data();
    view = svm_model{};
    view.param.svm_type = EPSILON_SVR;
    view.param.kernel_type = RBF;
    view.param.gamma = hyper.gamma();
    view.nr_class = 2;
    view.l = static_cast<int>(coef.size());
    view.SV = rows.data();
    view.sv_coef = coef_rows;
    view.rho = &rho;
  }
};

namespace {

void quiet(const char*) {}

// libsvm prints training progress through one global hook: set it once,
// before any thread trains.
void silence_libsvm() {
  static std::once_flag once;
  std::call_once(once, [] { svm_set_print_string_function(quiet); });
}

svm_parameter parameters(const SvrHyperparameters& h) {
  svm_parameter p{};
  p.svm_type = EPSILON_SVR;
  p.kernel_type = RBF;
  p.gamma = h.gamma();
  p.C = h.C;
  p.p = h.epsilon;
  p.eps = 1e-3;  // solver tolerance (libsvm's default), not the tube
  p.cache_size = 100;
  p.shrinking = 1;
  p.degree = 3;
  p.nu = 0.5;
  return p;
}

std::vector<svm_node> dense_nodes(const Eigen::MatrixXd& inputs) {
  const int d = static_cast<int>(inputs.cols());
  std::vector<svm_node> nodes;
  nodes.reserve(inputs.rows() * (d + 1));
  for (Eigen::Index r = 0; r < inputs.rows(); ++r) {
    for (int c = 0; c < d; ++c) nodes.push_back({c + 1, inputs(r, c)});
    nodes.push_back({-1, 0.0});
  }
  return nodes;
}

// libsvm takes gamma = 1/(2 sigma^2): a sigma whose gamma is 0 or not a
// normal number would train a constant.
void check_ranges(const SvrHyperparameters& h, const std::string& where) {
  // C <= 0 and epsilon < 0 are left to libsvm's own check (its message is passed on).
  if (!std::isfinite(h.C) || !std::isfinite(h.epsilon))
    throw InputError(where + ": C = " + number_text(h.C) + ", epsilon = " + number_text(h.epsilon) +
                     ": give finite values");
  if (!(h.sigma > 0.0) || !std::isnormal(h.gamma()))
    throw InputError(where + ": sigma = " + number_text(h.sigma) +
                     " is out of range; give a finite sigma > 0 whose 1/(2 sigma^2) is a normal number");
}

// A libsvm problem over dense rows, with its parameters checked (by us for
// the ranges, then by libsvm's svm_check_parameter, whose message is passed on).
struct LibsvmProblem {
  std::vector<svm_node> nodes;
  std::vector<svm_node*> rows;
  std::vector<double> y;
  svm_problem problem{};
  svm_parameter param{};

  LibsvmProblem(const Eigen::MatrixXd& inputs, const Eigen::VectorXd& targets, const SvrHyperparameters& h,
                const std::string& where)
      : nodes(dense_nodes(inputs)), y(targets.data(), targets.data() + targets.size()) {
    if (inputs.rows() == 0 || inputs.rows() != targets.size())
      throw InputError(where + ": " + std::to_string(inputs.rows()) + " input rows and " +
                       std::to_string(targets.size()) + " targets; give as many of each, at least one");
    check_ranges(h, where);
    silence_libsvm();
    for (Eigen::Index r = 0; r < inputs.rows(); ++r) rows.push_back(nodes.data() + r * (inputs.cols() + 1));
    problem = {static_cast<int>(rows.size()), y.data(), rows.data()};
    param = parameters(h);
    if (const char* message = svm_check_parameter(&problem, &param))
      throw InputError(where + ": libsvm rejects the hyperparameters: " + std::string(message) +
                       " (epsilon is libsvm's p; give C > 0, epsilon >= 0, sigma > 0)");
  }
};

}  // namespace

Eigen::VectorXd SvrRegressor::libsvm_cross_validation(const Eigen::MatrixXd& inputs,
                                                      const Eigen::VectorXd& targets,
                                                      const SvrHyperparameters& h, int folds,
                                                      unsigned seed, const std::string& where) {
  LibsvmProblem problem(inputs, targets, h, where);
  Eigen::VectorXd predicted(targets.size());
  static std::mutex rand_user;  // rand() is global and not thread-safe
  std::lock_guard lock(rand_user);
  std::srand(seed);
  svm_cross_validation(&problem.problem, &problem.param, folds, predicted.data());
  return predicted;
}

void SvrRegressor::check(const SvrHyperparameters& h, const std::string& where) {
  LibsvmProblem(Eigen::MatrixXd::Zero(1, 1), Eigen::VectorXd::Zero(1), h, where);
}

SvrRegressor SvrRegressor::train(const Eigen::MatrixXd& inputs, const Eigen::VectorXd& targets,
                                 const SvrHyperparameters& h, const std::string& where) {
  LibsvmProblem problem(inputs, targets, h, where);
  svm_model* trained = svm_train(&problem.problem, &problem.param);
  auto m = std::make_unique<Model>();
  m->hyper = h;
  m->dim = static_cast<int>(inputs.cols());
  m->rho = trained->rho[0];
  for (int i = 0; i < trained->l; ++i) {
    m->coef.push_back(trained->sv_coef[0][i]);
    // Dense copies: libsvm's rows point into `nodes`, which dies here.
    for (const svm_node* n = trained->SV[i]; n->index != -1; ++n) m->nodes.push_back(*n);
    m->nodes.push_back({-1, 0.0});
  }
  svm_free_and_destroy_model(&trained);
  m->link();
  return SvrRegressor(std::move(m));
}

SvrRegressor::SvrRegressor(std::unique_ptr<Model> model) : model_(std::move(model)) {}
SvrRegressor::SvrRegressor(const SvrRegressor& other) : model_(std::make_unique<Model>(*other.model_)) {
  model_->link();
}
SvrRegressor& SvrRegressor::operator=(const SvrRegressor& other) {
  if (this != &other) {
    model_ = std::make_unique<Model>(*other.model_);
    model_->link();
  }
  return *this;
}
SvrRegressor::SvrRegressor(SvrRegressor&&) noexcept = default;
SvrRegressor& SvrRegressor::operator=(SvrRegressor&&) noexcept = default;
SvrRegressor::~SvrRegressor() = default;

double SvrRegressor::predict(const Eigen::Ref<const Eigen::VectorXd>& input) const {
  std::vector<svm_node> row(model_->dim + 1);
  for (int c = 0; c < model_->dim; ++c) row[c] = {c + 1, input[c]};
  row[model_->dim] = {-1, 0.0};
  return svm_predict(&model_->view, row.data());
}

int SvrRegressor::dimension() const { return model_->dim; }
int SvrRegressor::support_vectors() const { return static_cast<int>(model_->coef.size()); }
const SvrHyperparameters& SvrRegressor::hyperparameters() const { return model_->hyper; }

nlohmann::json SvrRegressor::to_json() const {
  const Model& m = *model_;
  nlohmann::json vectors = nlohmann::json::array();
  for (std::size_t i = 0; i < m.coef.size(); ++i) {
    // Sparse as libsvm keeps them: [[index, value], ...] (zeros may be left out).
    nlohmann::json sv = nlohmann::json::array();
    for (const svm_node* n = m.rows[i]; n->index != -1; ++n) sv.push_back({n->index, n->value});
    vectors.push_back(sv);
  }
  return {{"epsilon", m.hyper.epsilon}, {"C", m.hyper.C},   {"sigma", m.hyper.sigma},
          {"gamma", m.hyper.gamma()},  {"dimension", m.dim}, {"rho", m.rho},
          {"coefficients", m.coef},    {"support_vectors", vectors}};
}

SvrRegressor SvrRegressor::from_json(const nlohmann::json& j, const std::string& where) {
  try {
    auto m = std::make_unique<Model>();
    m->hyper = {j.at("epsilon").get<double>(), j.at("C").get<double>(), j.at("sigma").get<double>()};
    m->dim = j.at("dimension").get<int>();
    m->rho = j.at("rho").get<double>();
    m->coef = j.at("coefficients").get<std::vector<double>>();
    const auto& vectors = j.at("support_vectors");
    if (vectors.size() != m->coef.size())
      throw InputError(where + ".support_vectors: " + std::to_string(vectors.size()) +
                       " vectors for " + std::to_string(m->coef.size()) + " coefficients");
    for (const auto& sv : vectors) {
      for (const auto& n : sv) m->nodes.push_back({n.at(0).get<int>(), n.at(1).get<double>()});
      m->nodes.push_back({-1, 0.0});
    }
    m->link();
    return SvrRegressor(std::move(m));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": not an SVR model (" + std::string(e.what()) + ")");
  }
}

}  // namespace hystbench
