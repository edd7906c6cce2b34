#pragma once

#include <glissade/body/body.h>
#include <glissade/body/energy_account.h>
#include <glissade/contact/contact_pair.h>
#include <glissade/contact/step/contact_problem.h>

#include <chrono>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * history.csv: one row per increment, with the columns the .prm asks for
   * in Output/History. Each item is checked against the bodies when the
   * writer is built, so a wrong body or point name stops the run before it
   * starts. The file is rewritten atomically (never half written), at
   * most once a second while the run goes on (rewriting it after every
   * increment made a long run quadratic: 1,200 steps spent seconds
   * formatting the same rows again), and by write() when the run ends,
   * stops or fails, or writes a checkpoint.
   */
  class HistoryWriter
  {
  public:
    HistoryWriter(const std::vector<std::string>           &items,
                  const std::vector<std::unique_ptr<Body>> &bodies,
                  ContactProblem                           &contact,
                  const std::string                        &filename,
                  const std::string                        &source,
                  const EnergyAccount                      *energies = nullptr);

    /** Adds a row; writes the file if a second has passed since the last
     *  write. */
    void
    record(const unsigned int increment,
           const double       time,
           const unsigned int newton_iterations);

    /** Writes the file with every row so far (if any is not written). */
    void
    write();

    const std::vector<std::string> &
    column_names() const
    {
      return columns;
    }

    /** The last recorded row (tests and summaries read it). */
    const std::vector<double> &
    last_row() const
    {
      return rows.back();
    }

    /** Every recorded row, increment 0 first. */
    const std::vector<std::vector<double>> &
    all_rows() const
    {
      return rows;
    }

    /** The value of a column in a row; throws if there is no such column. */
    double
    value(const std::vector<double> &row, const std::string &column) const
    {
      for (unsigned int c = 0; c < columns.size(); ++c)
        if (columns[c] == column)
          return row[c];
      throw std::out_of_range("history has no column '" + column + "'");
    }

    /** The rows so far, for a checkpoint (Boost serialization). */
    template <class Archive>
    void
    serialize_rows(Archive &archive)
    {
      archive &rows;
    }

  private:
    /**
     * One item of Output/History, "kind(arguments)": its columns and their
     * evaluator; an InputError naming `entry` if it cannot be read or
     * names what the scene does not have.
     */
    void
    add_item(const std::string                        &item,
             const std::vector<std::unique_ptr<Body>> &bodies,
             ContactProblem                           &contact,
             const EnergyAccount                      *energies,
             const std::string                        &entry);

    /** energies(): those of a dynamic scheme, a column each. */
    void
    add_energies(const EnergyAccount *energies,
                 const std::string   &item,
                 const std::string   &entry);

    /** contact_force(pair): its total force and active nodes. */
    void
    add_contact_force(const ContactPair &pair, const std::string &name);

    /** contact_node(pair, point(x, y)): the reaction and gap of a node. */
    void
    add_contact_node(const ContactPair &pair,
                     const std::string &name,
                     const std::string &location,
                     const std::string &item,
                     const std::string &entry);

    /** momentum(body), of a dynamic scheme. */
    void
    add_momentum(const Body        &body,
                 const std::string &name,
                 const std::string &item,
                 const std::string &entry);

    /** displacement(body, point(x, y)), of a vertex. */
    void
    add_displacement(const Body        &body,
                     const std::string &name,
                     const std::string &location,
                     const std::string &item,
                     const std::string &entry);

    /** reaction(body, boundary). */
    void
    add_reaction(const Body        &body,
                 const std::string &name,
                 const std::string &where,
                 const std::string &entry);

    std::string                                             filename;
    std::vector<std::string>                                columns;
    std::vector<std::function<void(std::vector<double> &)>> evaluators;
    std::vector<std::vector<double>>                        rows;
    /** Rows in the file, and when it was last written. */
    std::size_t                           rows_written = 0;
    std::chrono::steady_clock::time_point last_write;
  };
} // namespace glissade
