using System.Diagnostics;
using System.IO.Compression;
using System.Text.Json.Nodes;
using AcDream.App.Capture;
using AcDream.App.Scenes;
using AcDream.App.World;
using Xunit.Abstractions;

namespace AcDream.App.Tests;

/// <summary>
/// Captures and their replay: the committed capture of the default walk replays with every answer the same, a short
/// capture made now is its first lines, an answer edited by one bit is reported at its line with both answers, and a bad
/// line is refused by its line and field before anything is replayed.
/// </summary>
public sealed class CaptureTests(ITestOutputHelper log) : IDisposable
{
    /// <summary>The default walk's capture: <c>dotnet run --project src/AcDream.App -- --capture tests/AcDream.App.Tests/Corpus/holtburg-walk.capture.jsonl.gz</c>.</summary>
    private static readonly string Corpus = Path.Combine(AppContext.BaseDirectory, "Corpus", "holtburg-walk.capture.jsonl.gz");

    private readonly string _folder = Directory.CreateDirectory(Path.Combine(Path.GetTempPath(), "acdream-capture-tests-" + Guid.NewGuid().ToString("N"))).FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void The_default_walks_corpus_replays_with_every_answer_the_same()
    {
        var clock = Stopwatch.StartNew();
        (int status, string output, string error) = RunApp("replay", Corpus);
        log.WriteLine($"{output.Trim()} (the test: {clock.Elapsed.TotalSeconds:0.0} s)");
        error.Should().BeEmpty();
        status.Should().Be(0, output);
        output.Should().StartWith("replayed 235583 calls: all answers the same");
    }

    [Fact]
    public void A_capture_of_the_walks_first_frames_is_the_corpus_first_lines_and_replays_the_same()
    {
        string capture = Path.Combine(_folder, "short.capture.jsonl");
        (int status, string output, _) = RunApp("--frames", "60", "--quiet", "--out", _folder, "--capture", capture);
        status.Should().Be(0);
        string[] lines = File.ReadAllLines(capture);
        output.Should().Contain($"Capture: {capture} ({lines.Length - 1} calls)");
        lines.Length.Should().BeGreaterThan(1000, "60 frames of the player, 21 creatures, the camera and the commits");
        lines.Should().Equal(CorpusLines(lines.Length), "the corpus is what the main job records now");
        lines.Should().Contain(l => l.Contains("\"kind\":\"resolve\"")).And.Contain(l => l.Contains("\"kind\":\"cast\"")).And.Contain(l => l.Contains("\"kind\":\"moveMover\""));

        (status, output, _) = RunApp("replay", capture);
        status.Should().Be(0, output);
        output.Should().StartWith($"replayed {lines.Length - 1} calls: all answers the same");

        // The replay writes the walk's page beside the capture: the page of the scene's first 60 frames, byte for byte.
        string page = Path.Combine(_folder, "short.capture.html");
        output.Should().Contain($"Page: {page}");
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        File.ReadAllText(page).Should().Be(WalkPage.Build(SceneRunner.Run(scene, world, 60, null, new FrameDrawing()), world), "the replayed walk's page, with what the engine drew");
    }

    [Theory]
    [InlineData("resolve", "position", 0)]
    [InlineData("resolve", "normal", 2)]
    [InlineData("cast", "fraction", -1)]
    [InlineData("cast", "point", 1)]
    public void An_answer_edited_by_one_bit_is_reported_at_its_line_with_both_answers_and_the_inputs(string kind, string field, int index)
    {
        string[] lines = CorpusLines(4000);
        int at = Array.FindIndex(lines, 2500, l => l.Contains($"\"kind\":\"{kind}\"")); // a call after the first frames
        at.Should().BePositive();
        JsonObject call = JsonNode.Parse(lines[at])!.AsObject();
        JsonNode answer = call["answer"]![field]!;
        JsonValue bits = (index < 0 ? answer : answer[index]!).AsValue();
        string original = bits.GetValue<string>();
        string edited = (Convert.ToUInt32(original, 16) ^ 1u).ToString("X8");
        if (index < 0)
        {
            call["answer"]![field] = edited;
        }
        else
        {
            call["answer"]![field]![index] = edited;
        }

        lines[at] = call.ToJsonString();
        string capture = Write(lines);

        (int status, string output, string error) = RunApp("replay", capture);
        status.Should().Be(ReplayCommand.Differs, output + error);
        string[] report = output.Split('\n');
        report[0].Should().Be($"line {at + 1} ({kind}): the replayed answer differs from the recorded one");
        report[1].Should().StartWith("  recorded: {").And.Contain($"\"{edited}\"");
        report[2].Should().StartWith("  replayed: {").And.Contain($"\"{original}\"").And.NotContain($"\"{edited}\"");
        report[5].Should().StartWith("  inputs: {").And.Contain($"\"kind\":\"{kind}\"").And.Contain("\"request\":").And.NotContain("\"answer\"");
        output.Should().Contain("recorded, as numbers:").And.Contain("replayed, as numbers:");
    }

    [Theory]
    [InlineData("not JSON", "", "not JSON")]
    [InlineData("drop request.cell", "request.cell", "missing")]
    [InlineData("span as text", "span", "expected a whole number")]
    [InlineData("unknown kind", "kind", "unknown kind \"teleport\"")]
    [InlineData("short float", "answer.position[1]", "8 hex digits")]
    [InlineData("extra field", "request.speed", "unknown field")]
    [InlineData("bad outcome", "answer.outcome", "is not one of")]
    public void A_bad_line_is_refused_naming_its_line_and_field_and_nothing_is_replayed(string edit, string field, string what)
    {
        string[] lines = CorpusLines(3000);
        int at = Array.FindLastIndex(lines, l => l.Contains("\"kind\":\"resolve\"")); // near the end: the lines before it are good
        JsonObject call = JsonNode.Parse(lines[at])!.AsObject();
        switch (edit)
        {
            case "not JSON":
                lines[at] = lines[at][..^1];
                break;
            case "drop request.cell":
                call["request"]!.AsObject().Remove("cell");
                break;
            case "span as text":
                call["span"] = "16";
                break;
            case "unknown kind":
                call["kind"] = "teleport";
                break;
            case "short float":
                call["answer"]!["position"]![1] = "4231";
                break;
            case "extra field":
                call["request"]!["speed"] = "3F800000";
                break;
            default:
                call["answer"]!["outcome"] = "Flew";
                break;
        }

        lines[at] = edit == "not JSON" ? lines[at] : call.ToJsonString();
        string capture = Write(lines);

        Action read = () => CaptureReader.ReadFile(capture);
        read.Should().Throw<CaptureFormatException>().Which.Should().Match<CaptureFormatException>(e => e.Line == at + 1 && e.Field == field);
        (int status, string output, string error) = RunApp("replay", capture);
        status.Should().Be(2);
        output.Should().BeEmpty("nothing is replayed");
        error.Should().Contain(field.Length == 0 ? $"line {at + 1}: " : $"line {at + 1}, field \"{field}\": ").And.Contain(what);
    }

    [Fact]
    public void A_capture_with_no_header_or_of_another_format_is_refused_at_line_1()
    {
        string[] lines = CorpusLines(3);
        RunApp("replay", Write([])).Status.Should().Be(2);
        RunApp("replay", Write(lines[1..])).Error.Should().Contain("line 1, field \"kind\"");
        RunApp("replay", Write([lines[0].Replace("acdream-capture", "other"), .. lines[1..]])).Error.Should().Contain("line 1, field \"format\"");
        RunApp("replay", Write([lines[0].Replace("embedded default", "no-such-scene.json"), .. lines[1..]])).Error.Should().Contain("line 1, field \"scene\"");
        RunApp("replay", Path.Combine(_folder, "missing.jsonl")).Error.Should().Contain("cannot read the capture");
        RunApp("replay").Status.Should().Be(2);
    }

    [Fact]
    public void Of_several_bad_lines_the_first_is_named()
    {
        string[] lines = CorpusLines(3000);
        lines[2800] = lines[2800].Replace("\"kind\":", "\"kinds\":");
        lines[400] = "{\"kind\":\"commit\"}";
        lines[1900] = "[]";
        Action read = () => CaptureReader.ReadFile(Write(lines));
        read.Should().Throw<CaptureFormatException>().Which.Should().Match<CaptureFormatException>(e => e.Line == 401 && e.Field == "answer");
    }

    [Fact]
    public void The_usage_text_names_the_capture_option_and_the_replay_command()
    {
        (int status, string output, _) = RunApp("--help");
        status.Should().Be(0);
        output.Should().Contain("--capture FILE").And.Contain("-- replay FILE").And.Contain("replay FILE      replays a capture");
    }

    private static string[] CorpusLines(int count)
    {
        using var reader = new StreamReader(new GZipStream(File.OpenRead(Corpus), CompressionMode.Decompress));
        var lines = new List<string>(count);
        for (string? line; lines.Count < count && (line = reader.ReadLine()) is not null;)
        {
            lines.Add(line);
        }

        return [.. lines];
    }

    private string Write(string[] lines)
    {
        string path = Path.Combine(_folder, Guid.NewGuid().ToString("N") + ".capture.jsonl");
        File.WriteAllLines(path, lines);
        return path;
    }

    private static (int Status, string Output, string Error) RunApp(params string[] args)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        int status = MainJob.Run(args, output, error);
        return (status, output.ToString(), error.ToString());
    }
}
