#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <softopt/optimization/checkpoint.h>

#include <cstdint>
#include <filesystem>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

namespace softopt
{
  namespace Checkpoint
  {
    namespace
    {
      constexpr std::uint64_t magic = 0x736f66746f707433; // "softopt3"
      // Older checkpoints were written after the iteration's mesh update
      // and without the accepted design: a run cannot go on from them.
      constexpr std::uint64_t magic_2 = 0x736f66746f707432; // "softopt2"
      constexpr std::uint64_t magic_1 = 0x736f66746f707431; // "softopt1"

      /** The checkpoint to read: "checkpoint", or "checkpoint.old" if a
       * run was killed between the two renames of save(). */
      std::string
      existing_directory(const std::string &output_directory)
      {
        const auto dir = directory(output_directory);
        return std::filesystem::exists(dir) ? dir : dir + ".old";
      }

      std::string
      rank_file(const std::string &dir, const MPI_Comm comm)
      {
        return dir + "/rank-" +
               std::to_string(Utilities::MPI::this_mpi_process(comm)) + ".bin";
      }

      template <typename T>
      void
      write_value(std::ostream &out, const T &value)
      {
        out.write(reinterpret_cast<const char *>(&value), sizeof(T));
      }

      template <typename T>
      T
      read_value(std::istream &in)
      {
        T value{};
        in.read(reinterpret_cast<char *>(&value), sizeof(T));
        return value;
      }

      /** The locally owned entries of @p v, in index order. */
      void
      write_vector(std::ostream &out, const Vector &v)
      {
        const auto owned = v.locally_owned_elements();
        const std::vector<types::global_dof_index> indices(owned.begin(),
                                                           owned.end());
        std::vector<double> values(indices.size());
        v.extract_subvector_to(indices.begin(), indices.end(), values.begin());
        write_value<std::uint64_t>(out, values.size());
        out.write(reinterpret_cast<const char *>(values.data()),
                  values.size() * sizeof(double));
      }

      void
      read_vector(std::istream &in, Vector &v, const std::string &file)
      {
        const auto owned = v.locally_owned_elements();
        const auto size  = read_value<std::uint64_t>(in);
        AssertThrow(in, ExcMessage("The checkpoint " + file + " is truncated."));
        AssertThrow(size == owned.n_elements(),
                    ExcMessage(file + " was written for another mesh or "
                                      "another number of MPI ranks."));
        std::vector<double> values(owned.n_elements());
        in.read(reinterpret_cast<char *>(values.data()),
                values.size() * sizeof(double));
        AssertThrow(in, ExcMessage("The checkpoint " + file + " is truncated."));
        std::vector<types::global_dof_index> indices(owned.begin(), owned.end());
        v.set(indices, values);
        v.compress(VectorOperation::insert);
      }

      void
      write_states(std::ostream &out, const std::map<double, Vector> &states)
      {
        write_value<std::uint32_t>(out, states.size());
        for (const auto &[load_factor, a] : states)
          {
            write_value(out, load_factor);
            write_vector(out, a);
          }
      }

      std::map<double, Vector>
      read_states(std::istream &in, const Vector &state_template, const std::string &file)
      {
        std::map<double, Vector> states;
        const auto n_states = read_value<std::uint32_t>(in);
        for (unsigned int i = 0; i < n_states && in; ++i)
          {
            const auto load_factor = read_value<double>(in);
            Vector     a           = state_template;
            read_vector(in, a, file);
            states.emplace(load_factor, a);
          }
        return states;
      }
    } // namespace



    std::string
    directory(const std::string &output_directory)
    {
      return output_directory + "/checkpoint";
    }



    void
    save(const std::string   &output_directory,
         const unsigned int   iteration,
         const DesignIterate &x)
    {
      namespace fs     = std::filesystem;
      const auto  comm = x.d.get_mpi_communicator();
      const bool  root = Utilities::MPI::this_mpi_process(comm) == 0;
      const auto  dir  = directory(output_directory);
      const auto  next = dir + ".new";
      if (root)
        {
          fs::remove_all(next);
          fs::create_directories(next);
        }
      MPI_Barrier(comm);
      if (root && !x.mesh_file.empty())
        {
          // By its name: it lives in the output directory, which may move.
          std::ofstream out(next + "/mesh");
          out << std::filesystem::path(x.mesh_file).filename().string() << '\n';
          AssertThrow(out, ExcMessage("Writing " + next + "/mesh failed."));
        }
      {
        const auto    file = rank_file(next, comm);
        std::ofstream out(file, std::ios::binary);
        write_value(out, magic);
        write_value<std::uint32_t>(out, Utilities::MPI::n_mpi_processes(comm));
        write_value<std::uint32_t>(out, iteration);
        write_vector(out, x.d);
        write_vector(out, x.accepted);
        write_vector(out, x.X_o);
        write_vector(out, x.psi);
        x.mma->save(out);
        write_states(out, x.states);
        // The secant: the positions of the design of these states, and the
        // design before it.
        const auto &previous = x.secant.previous_design();
        write_value<std::uint8_t>(out, x.secant.last_positions().size() > 0);
        if (x.secant.last_positions().size() > 0)
          write_vector(out, x.secant.last_positions());
        write_value<std::uint8_t>(out, !previous.states.empty());
        if (!previous.states.empty())
          {
            write_vector(out, previous.X);
            write_states(out, previous.states);
          }
        AssertThrow(out, ExcMessage("Writing the checkpoint " + file + " failed."));
      }
      // Every rank has written: swap the new checkpoint in.
      MPI_Barrier(comm);
      if (root)
        {
          fs::remove_all(dir + ".old");
          if (fs::exists(dir))
            fs::rename(dir, dir + ".old");
          fs::rename(next, dir);
          fs::remove_all(dir + ".old");
        }
      MPI_Barrier(comm);
    }



    std::string
    mesh_file(const std::string &output_directory)
    {
      std::string   name;
      std::ifstream in(existing_directory(output_directory) + "/mesh");
      std::getline(in, name);
      if (name.empty())
        return name;
      const std::string file = output_directory + "/" + name;
      AssertThrow(std::ifstream(file).good(),
                  ExcMessage("--restart: the checkpoint in <" + output_directory +
                             "> continues on the mesh <" + file + "> (a new "
                             "mesh of the design), which cannot be read: " +
                             std::strerror(errno) + ". Restore it, or start "
                             "over with --start-over."));
      return file;
    }



    unsigned int
    load(const std::string &output_directory,
         const Vector      &state_template,
         DesignIterate     &x)
    {
      const auto    comm = x.d.get_mpi_communicator();
      const auto    file = rank_file(existing_directory(output_directory), comm);
      std::ifstream in(file, std::ios::binary);
      AssertThrow(in,
                  ExcMessage("--restart: there is no checkpoint " + file +
                             " (checkpoints are written every \"Checkpoint "
                             "interval\" iterations of subsection Optimization "
                             "into the output directory)."));
      const auto file_magic = read_value<std::uint64_t>(in);
      AssertThrow(file_magic != magic_2 && file_magic != magic_1,
                  ExcMessage("--restart: " + file + " was written by an older "
                             "softopt, which this one cannot continue; start "
                             "the run afresh (without --restart)."));
      AssertThrow(file_magic == magic,
                  ExcMessage(file + " is not a softopt checkpoint."));
      const auto n_ranks = read_value<std::uint32_t>(in);
      AssertThrow(n_ranks == Utilities::MPI::n_mpi_processes(comm),
                  ExcMessage("--restart: the checkpoint was written by " +
                             std::to_string(n_ranks) +
                             " MPI ranks; restart with mpirun -np " +
                             std::to_string(n_ranks) + "."));
      const auto iteration = read_value<std::uint32_t>(in);
      x.mesh_file          = mesh_file(output_directory);
      read_vector(in, x.d, file);
      read_vector(in, x.accepted, file);
      read_vector(in, x.X_o, file);
      read_vector(in, x.psi, file);
      try
        {
          x.mma->load(in);
        }
      catch (const std::exception &)
        {
          AssertThrow(false, ExcMessage("The checkpoint " + file + " is truncated."));
        }
      x.states = read_states(in, state_template, file);
      Vector                  X_last;
      SecantPredictor::Design previous;
      if (read_value<std::uint8_t>(in) && in)
        {
          X_last = x.X_o;
          read_vector(in, X_last, file);
        }
      if (read_value<std::uint8_t>(in) && in)
        {
          previous.X = x.X_o;
          read_vector(in, previous.X, file);
          previous.states = read_states(in, state_template, file);
        }
      x.secant.restore(X_last, previous);
      AssertThrow(in, ExcMessage("The checkpoint " + file + " is truncated."));
      return iteration;
    }
  } // namespace Checkpoint
} // namespace softopt
