// Test helper: builds a fn::Expr from a Lisp-like text, so function-machine tests read like the
// formulas they check:
//   "(+ (* x x) (sin y))"          x y z are parameters 0 1 2, pN is parameter N
//   "(sum 0 1 (p 0) (* i0 i0))"    (sum SLOT FROM TO BODY), iN is the iteration variable of slot N
//   "(call 2 .x a b c)"            (call FUNCTION [.member] ARGS...), "(internal 61 x y z 1)"
// Ops are named as fn::opName gives them ("+", "<=", "select", "?:", "!", "neg" for unary minus).
// Every node's loc is its 1-based character offset in the text, so errors can be checked.
#pragma once
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "rays/fn/expr.h"

namespace rays::fn::testing {

class SExpr {
public:
    explicit SExpr(const std::string& text) : s_(text) {}

    Expr parse() {
        Expr e;
        e.root = node(e);
        skip();
        if (i_ != s_.size()) throw std::runtime_error("trailing text in " + s_);
        return e;
    }

private:
    void skip() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    std::string word() {
        skip();
        size_t b = i_;
        while (i_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[i_])) && s_[i_] != '(' && s_[i_] != ')') ++i_;
        return s_.substr(b, i_ - b);
    }
    static Op opNamed(const std::string& w) {
        if (w == "neg") return Op::Neg;
        for (int o = 0; o <= static_cast<int>(Op::Internal); ++o)
            if (opName(static_cast<Op>(o)) == w) return static_cast<Op>(o);
        throw std::runtime_error("unknown op " + w);
    }
    int32_t node(Expr& e) {
        skip();
        const int32_t loc = static_cast<int32_t>(i_) + 1;
        if (i_ < s_.size() && s_[i_] == '(') {
            ++i_;
            const std::string head = word();
            std::vector<int32_t> kids;
            int32_t id = 0;
            Member member = Member::None;
            Op op;
            if (head == "sum" || head == "prod") {
                op = head == "sum" ? Op::Sum : Op::Prod;
                id = std::stoi(word());
            } else if (head == "call" || head == "internal") {
                op = head == "call" ? Op::Call : Op::Internal;
                id = std::stoi(word());
                skip();
                if (op == Op::Call && i_ < s_.size() && s_[i_] == '.') {
                    ++i_;
                    auto m = memberFromName(word());
                    if (!m) throw std::runtime_error("bad member");
                    member = *m;
                }
            } else if (head == "p") {
                const int32_t slot = std::stoi(word());
                skip();
                ++i_;  // ')'
                return e.param(slot, loc);
            } else {
                op = opNamed(head);
            }
            for (;;) {
                skip();
                if (i_ >= s_.size()) throw std::runtime_error("missing ) in " + s_);
                if (s_[i_] == ')') {
                    ++i_;
                    break;
                }
                kids.push_back(node(e));
            }
            return e.add(op, kids, id, loc, member);
        }
        const std::string w = word();
        if (w == "x") return e.param(0, loc);
        if (w == "y") return e.param(1, loc);
        if (w == "z") return e.param(2, loc);
        if (w.size() > 1 && w[0] == 'p' && std::isdigit(static_cast<unsigned char>(w[1]))) return e.param(std::stoi(w.substr(1)), loc);
        if (w.size() > 1 && w[0] == 'i' && std::isdigit(static_cast<unsigned char>(w[1]))) return e.local(std::stoi(w.substr(1)), loc);
        if (w == "nan") return e.constant(std::nan(""), loc);
        if (w == "inf") return e.constant(INFINITY, loc);
        return e.constant(std::strtod(w.c_str(), nullptr), loc);
    }

    std::string s_;
    size_t i_ = 0;
};

/// The tree of `text` (see SExpr).
inline Expr sexpr(const std::string& text) { return SExpr(text).parse(); }

}  // namespace rays::fn::testing
