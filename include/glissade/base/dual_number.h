#pragma once

#include <array>
#include <cmath>

namespace glissade
{
  /**
   * A number with its first derivatives with respect to N variables
   * (forward-mode automatic differentiation). Used where a geometric
   * quantity depends on many coordinates through a long chain (the mortar
   * integrals over a segment pair: projections, the overlap's ends, Gauss
   * points, the dual shape functions), so that its derivatives are exact
   * without a hand-written chain rule for every step.
   */
  template <int N>
  struct Dual
  {
    double                value = 0.;
    std::array<double, N> derivative{};

    Dual() = default;

    /** A constant. */
    Dual(const double v)
      : value(v)
    {}

    /** Variable `index` at value v. */
    static Dual
    variable(const double v, const unsigned int index)
    {
      Dual x(v);
      x.derivative[index] = 1.;
      return x;
    }

    Dual &
    operator+=(const Dual &b)
    {
      value += b.value;
      for (int i = 0; i < N; ++i)
        derivative[i] += b.derivative[i];
      return *this;
    }

    Dual &
    operator-=(const Dual &b)
    {
      value -= b.value;
      for (int i = 0; i < N; ++i)
        derivative[i] -= b.derivative[i];
      return *this;
    }

    Dual &
    operator*=(const Dual &b)
    {
      for (int i = 0; i < N; ++i)
        derivative[i] = derivative[i] * b.value + value * b.derivative[i];
      value *= b.value;
      return *this;
    }

    Dual &
    operator/=(const Dual &b)
    {
      const double q = value / b.value;
      for (int i = 0; i < N; ++i)
        derivative[i] = (derivative[i] - q * b.derivative[i]) / b.value;
      value = q;
      return *this;
    }
  };

  template <int N>
  Dual<N>
  operator+(Dual<N> a, const Dual<N> &b)
  {
    return a += b;
  }

  template <int N>
  Dual<N>
  operator-(Dual<N> a, const Dual<N> &b)
  {
    return a -= b;
  }

  template <int N>
  Dual<N>
  operator-(Dual<N> a)
  {
    a.value = -a.value;
    for (auto &d : a.derivative)
      d = -d;
    return a;
  }

  template <int N>
  Dual<N>
  operator*(Dual<N> a, const Dual<N> &b)
  {
    return a *= b;
  }

  template <int N>
  Dual<N>
  operator/(Dual<N> a, const Dual<N> &b)
  {
    return a /= b;
  }

  template <int N>
  Dual<N>
  operator+(Dual<N> a, const double b)
  {
    a.value += b;
    return a;
  }

  template <int N>
  Dual<N>
  operator+(const double b, Dual<N> a)
  {
    a.value += b;
    return a;
  }

  template <int N>
  Dual<N>
  operator-(Dual<N> a, const double b)
  {
    a.value -= b;
    return a;
  }

  template <int N>
  Dual<N>
  operator-(const double b, const Dual<N> &a)
  {
    return -a + b;
  }

  template <int N>
  Dual<N>
  operator*(Dual<N> a, const double b)
  {
    a.value *= b;
    for (auto &d : a.derivative)
      d *= b;
    return a;
  }

  template <int N>
  Dual<N>
  operator*(const double b, const Dual<N> &a)
  {
    return a * b;
  }

  template <int N>
  Dual<N>
  sqrt(const Dual<N> &a)
  {
    Dual<N>      r(std::sqrt(a.value));
    const double half_inverse = 0.5 / r.value;
    for (int i = 0; i < N; ++i)
      r.derivative[i] = a.derivative[i] * half_inverse;
    return r;
  }
} // namespace glissade
