// `glint farm submit SCENE -o OUT --tiles N | --frames A-B`: a render split into parts for a
// cluster scheduler. The job is a plain list of glint commands (tasks.txt: one `glint render`
// per tile or frame; finish.txt: the `glint merge` that joins or checks them), so any scheduler
// can run it; for Slurm this writes a job array over tasks.txt and a finishing job that starts
// after every task has ended, and submits both with sbatch. Tasks skip parts that are already
// complete (render --skip-existing), so submitting again renders only what is missing.
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/parts.h"
#include "formats/pov/command_line.h"
#include "core/error.h"

namespace glint::app {

// POV-Ray's options (formats/pov/command_line.h).
using pov::AnimationPlan;
using pov::PovFrame;
using pov::PovSettings;
using pov::apply_frame_range;
using pov::frame_output_name;
using pov::plan_animation;
using pov::read_pov_arguments;

CLI::App* add_farm_command(CLI::App& app, FarmArgs& args) {
    CLI::App* farm = app.add_subcommand(
        "farm", "Split a render into tiles or frames for a cluster scheduler (Slurm)");
    farm->require_subcommand(1);
    CLI::App* cmd = farm->add_subcommand(
        "submit",
        "Write the job (one glint render per tile or frame, then a glint merge) and submit it "
        "to Slurm with sbatch: a job array, and a finishing job after it. Flags this command "
        "does not know, and POV-Ray switches, go to every glint render (--width, --aa, "
        "--integrator path, +A0.3, ...)");
    cmd->add_option("scene", args.scene, "POV-Ray scene file")->required();
    cmd->add_option("-o,--output", args.output, "The whole image (tiles) or the frames' name")
        ->required();
    cmd->add_option("--tiles", args.tiles, "Split the image into N rectangles, one task each")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--frames", args.frames, "One task per frame A to B of the animation");
    cmd->add_option("--partition", args.partition, "Slurm partition (sbatch --partition)");
    cmd->add_option("--dir", args.dir,
                    "Folder for the job's files, parts and logs (default: OUT-stem.farm beside "
                    "OUT); it must be visible to every node");
    cmd->add_option("--cpus-per-task", args.cpus,
                    "CPUs Slurm gives each task (its glint render uses them all)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--retries", args.retries,
                    "Attempts a task makes after a failed one before it fails")
        ->capture_default_str()
        ->check(CLI::Range(0, 100));
    cmd->add_flag("--dry-run", args.dry_run, "Print the job's files instead of writing and submitting them");
    cmd->add_flag("--no-submit", args.no_submit,
                  "Write the job's files and folders but submit nothing: tasks.txt is one "
                  "command per line, for any scheduler (finish.txt after all of them)");
    cmd->allow_extras();
    cmd->parse_complete_callback([cmd, &args] { args.render_args = cmd->remaining(); });
    return cmd;
}

namespace {

namespace fs = std::filesystem;

std::string quote(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-+=/.,:@%") == std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string join(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) line += (line.empty() ? "" : " ") + quote(w);
    return line;
}

// A value in an #SBATCH line: sbatch strips double quotes around one that has spaces.
std::string directive(const std::string& v) {
    return v.find_first_of(" \t") == std::string::npos ? v : "\"" + v + "\"";
}

std::string self_path() {
    std::error_code ec;
    fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("glint") : p.string();
}

// The render settings every task will use, parsed as `glint render` parses them: a bad flag
// fails here, before anything is submitted.
RenderArgs parse_render_args(const FarmArgs& f) {
    CLI::App app("glint", "glint");
    RenderArgs ra;
    add_render_command(app, ra);
    std::vector<std::string> argv = {"glint", "render", f.scene, "-o", f.output};
    argv.insert(argv.end(), f.render_args.begin(), f.render_args.end());
    std::vector<std::string> rest = take_pov_arguments(argv, ra.pov_args);
    std::vector<char*> cargv;
    for (std::string& a : rest) cargv.push_back(a.data());
    try {
        app.parse(static_cast<int>(cargv.size()), cargv.data());
    } catch (const CLI::ParseError& e) {
        throw Error(ErrorKind::Usage, {}, std::string("the render flags: ") + e.what());
    }
    return effective_render_args(ra);
}

bool has_flag(const std::vector<std::string>& args, const std::string& flag) {
    for (const std::string& a : args)
        if (a == flag || a.rfind(flag + "=", 0) == 0) return true;
    return false;
}

struct Job {
    std::vector<std::string> tasks;  // one command line each
    std::string finish;              // the merge or verify command line
    std::vector<std::string> outputs;
};

std::string array_script(const FarmArgs& f, const std::string& dir, const Job& job,
                         const std::string& name) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# glint farm: one task per line of tasks.txt (written by glint farm submit).\n"
      << "#SBATCH --job-name=" << name << "\n"
      << "#SBATCH --array=0-" << job.tasks.size() - 1 << "\n"
      << "#SBATCH --requeue\n"
      << "#SBATCH --chdir=" << directive(fs::current_path().string()) << "\n"
      << "#SBATCH --output=" << directive(dir + "/logs/task-%a.log") << "\n";
    if (!f.partition.empty()) s << "#SBATCH --partition=" << f.partition << "\n";
    if (f.cpus > 0) s << "#SBATCH --cpus-per-task=" << f.cpus << "\n";
    s << "set -u\n"
      << "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " << quote(dir + "/tasks.txt") << ")\n"
      << "if [ -z \"$line\" ]; then echo \"glint farm: no task $SLURM_ARRAY_TASK_ID\" >&2; exit 1; fi\n"
      << "for attempt in $(seq 1 " << f.retries + 1 << "); do\n"
      << "    echo \"glint farm: task $SLURM_ARRAY_TASK_ID, attempt $attempt: $line\" >&2\n"
      << "    if eval \"$line\"; then exit 0; fi\n"
      << "    sleep 1\n"
      << "done\n"
      << "echo \"glint farm: task $SLURM_ARRAY_TASK_ID failed " << f.retries + 1
      << " times\" >&2\n"
      << "exit 1\n";
    return s.str();
}

std::string finish_script(const FarmArgs& f, const std::string& dir, const std::string& name) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# glint farm: after every task of the array has ended, join (or check) the parts.\n"
      << "# Fails, naming what is missing, if a task did not leave its part.\n"
      << "#SBATCH --job-name=" << name << "-finish\n"
      << "#SBATCH --chdir=" << directive(fs::current_path().string()) << "\n"
      << "#SBATCH --output=" << directive(dir + "/logs/finish.log") << "\n";
    if (!f.partition.empty()) s << "#SBATCH --partition=" << f.partition << "\n";
    s << "set -u\n"
      << "eval \"$(cat " << quote(dir + "/finish.txt") << ")\"\n";
    return s.str();
}

// Runs a command, returns the last line of its standard output (its standard error goes to
// ours, so sbatch's warnings and errors reach the user as it writes them); throws when it
// fails.
std::string run_command(const std::string& command) {
    std::FILE* p = popen(command.c_str(), "r");
    if (!p) throw Error(ErrorKind::Render, {}, "cannot run " + command);
    std::string out;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
    const int rc = pclose(p);
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    if (rc != 0)
        throw Error(ErrorKind::Render, {},
                    command + " failed (exit status " + std::to_string(WEXITSTATUS(rc)) + ")");
    const size_t nl = out.rfind('\n');
    return nl == std::string::npos ? out : out.substr(nl + 1);
}

void write_text(const std::string& path, const std::string& text, bool executable) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw Error(ErrorKind::Output, {}, "cannot write " + path);
    if (executable) fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec,
                                    fs::perm_options::add);
}

}  // namespace

int run_farm(const FarmArgs& f) {
    if ((f.tiles > 0) == !f.frames.empty())
        throw Error(ErrorKind::Usage, {}, "give one of --tiles N and --frames A-B");
    for (const char* own : {"--region", "--frame", "--frames", "--skip-existing", "-o", "--output"})
        if (has_flag(f.render_args, own))
            throw Error(ErrorKind::Usage, {},
                        std::string(own) + " is the farm's to set for each task; leave it out");
    const RenderArgs ra = parse_render_args(f);
    std::error_code ec;
    const std::string scene = fs::absolute(f.scene).lexically_normal().string();
    const std::string output = fs::absolute(f.output).lexically_normal().string();
    const std::string stem = fs::path(output).stem().string();
    const std::string ext = fs::path(output).extension().string();
    const std::string dir = f.dir.empty()
                                ? (fs::path(output).parent_path() / (stem + ".farm")).string()
                                : fs::absolute(f.dir).lexically_normal().string();
    const std::string glint = self_path();
    std::vector<std::string> common = f.render_args;
    if (f.cpus > 0 && !has_flag(common, "--threads")) {
        common.push_back("--threads");
        common.push_back(std::to_string(f.cpus));
    }
    common.push_back("--skip-existing");
    common.push_back("--progress");
    common.push_back("none");

    Job job;
    if (f.tiles > 0) {
        if (plan_animation(read_pov_arguments(ra.pov_args)).animated)
            throw Error(ErrorKind::Usage, {},
                        "--tiles splits one image, and the render flags make an animation "
                        "(POV-Ray's +KFI/+KFF): use --frames");
        const std::vector<render::Region> tiles =
            split_into_tiles(ra.scene.width, ra.scene.height, f.tiles);
        int digits = 1;
        for (size_t v = tiles.size() - 1; v >= 10; v /= 10) ++digits;
        std::vector<std::string> merge = {glint, "merge", "-o", output};
        for (size_t i = 0; i < tiles.size(); ++i) {
            std::string n = std::to_string(i);
            n.insert(0, static_cast<size_t>(std::max(0, digits - static_cast<int>(n.size()))), '0');
            const std::string part = dir + "/parts/part-" + n + ext;
            std::vector<std::string> cmd = {glint, "render", scene, "-o", part, "--region",
                                            region_string(tiles[i])};
            cmd.insert(cmd.end(), common.begin(), common.end());
            job.tasks.push_back(join(cmd));
            merge.push_back(part);
            job.outputs.push_back(part);
        }
        job.finish = join(merge);
    } else {
        const FrameRange range = parse_frame_range(f.frames, "--frames");
        // The frames' file names, as glint render names them (POV-Ray's rule).
        PovSettings pov = read_pov_arguments(ra.pov_args);
        apply_frame_range(pov, range.first, range.last);
        const AnimationPlan plan = plan_animation(pov);
        if (!plan.animated || plan.frames.empty())
            throw Error(ErrorKind::Usage, {},
                        "--frames " + f.frames + ": not an animation of two or more frames");
        std::vector<std::string> verify = {glint, "merge", "--verify"};
        for (const PovFrame& frame : plan.frames) {
            std::vector<std::string> cmd = {glint, "render", scene, "-o", output, "--frames",
                                            f.frames, "--frame", std::to_string(frame.number)};
            cmd.insert(cmd.end(), common.begin(), common.end());
            job.tasks.push_back(join(cmd));
            const std::string out = frame_output_name(output, frame.number, plan.digits);
            verify.push_back(out);
            job.outputs.push_back(out);
        }
        job.finish = join(verify);
    }

    const std::string name = "glint-" + stem;
    std::string tasks_txt, finish_txt = job.finish + "\n";
    for (const std::string& t : job.tasks) tasks_txt += t + "\n";
    const std::string array = array_script(f, dir, job, name);
    const std::string finish = finish_script(f, dir, name);
    if (f.dry_run) {
        std::printf("# %s/tasks.txt (%zu tasks)\n%s\n# %s/finish.txt\n%s\n# %s/array.sbatch\n%s\n"
                    "# %s/finish.sbatch\n%s\n# submitted with:\n#   sbatch --parsable %s/array.sbatch\n"
                    "#   sbatch --parsable --dependency=afterany:JOB %s/finish.sbatch\n",
                    dir.c_str(), job.tasks.size(), tasks_txt.c_str(), dir.c_str(),
                    finish_txt.c_str(), dir.c_str(), array.c_str(), dir.c_str(), finish.c_str(),
                    dir.c_str(), dir.c_str());
        return kExitOk;
    }
    fs::create_directories(fs::path(dir) / "logs", ec);
    if (f.tiles > 0) fs::create_directories(fs::path(dir) / "parts", ec);
    if (!fs::is_directory(fs::path(dir) / "logs"))
        throw Error(ErrorKind::Output, {}, "cannot create " + dir + "/logs");
    write_text(dir + "/tasks.txt", tasks_txt, false);
    write_text(dir + "/finish.txt", finish_txt, false);
    write_text(dir + "/array.sbatch", array, true);
    write_text(dir + "/finish.sbatch", finish, true);
    if (f.no_submit) {
        std::printf("wrote %s/tasks.txt (%zu tasks) and %s/finish.txt\n", dir.c_str(),
                    job.tasks.size(), dir.c_str());
        return kExitOk;
    }
    // `sbatch --parsable` prints "jobid" or "jobid;cluster".
    std::string id = run_command("sbatch --parsable " + quote(dir + "/array.sbatch"));
    id = id.substr(0, id.find(';'));
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw Error(ErrorKind::Render, {}, "sbatch gave no job id: " + id);
    std::string fid = run_command("sbatch --parsable --dependency=afterany:" + id + " " +
                                  quote(dir + "/finish.sbatch"));
    fid = fid.substr(0, fid.find(';'));
    std::printf("submitted job array %s (%zu tasks) and finishing job %s; "
                "logs in %s/logs\n", id.c_str(), job.tasks.size(), fid.c_str(), dir.c_str());
    std::printf("%s %s\n", id.c_str(), fid.c_str());
    return kExitOk;
}

}  // namespace glint::app
