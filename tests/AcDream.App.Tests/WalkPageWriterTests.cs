using System.Text.Json;
using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Tests;

/// <summary>The walk page as written (<see cref="WalkPage"/>), read without a browser: its data against the walk's record, and the main job's failure to write it.</summary>
public sealed class WalkPageWriterTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "acdream-page-writer-" + Guid.NewGuid().ToString("N"));

    public WalkPageWriterTests() => Directory.CreateDirectory(_folder);

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void Page_DataDecoded_GivesEachFramesFeetEyeCellAndOutcome_ToTheMillimetre_AndLoadsNothingFromOutside()
    {
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        WalkRecord record = SceneRunner.Run(scene, world, 400);

        string html = WalkPage.Build(record, world);

        html.Should().NotContain("<script src", "three.js is inside the page").And.NotContain("<link");
        html.Should().Contain("<script type=\"importmap\">{\"imports\":{\"three\":\"data:text/javascript;base64,");
        const string open = "<script type=\"application/json\" id=\"walk-data\">";
        int start = html.IndexOf(open, StringComparison.Ordinal) + open.Length;
        using JsonDocument data = JsonDocument.Parse(html[start..html.IndexOf("</script>", start, StringComparison.Ordinal)]);
        JsonElement frames = data.RootElement.GetProperty("frames");
        frames.GetProperty("count").GetInt32().Should().Be(record.Samples.Count);
        int[] Column(string name) => [.. frames.GetProperty(name).EnumerateArray().Select(e => e.GetInt32())];
        int[] Undelta(string name)
        {
            int sum = 0;
            return [.. Column(name).Select(d => sum += d)];
        }

        int[] x = Undelta("x"), y = Undelta("y"), z = Undelta("z"), eyeZ = Undelta("eyeZ"), frame = Undelta("frame"), cell = Column("cell"), outcome = Column("outcome");
        string[] cellIds = [.. frames.GetProperty("cellIds").EnumerateArray().Select(e => e.GetString()!)];
        string[] outcomes = [.. data.RootElement.GetProperty("outcomes").EnumerateArray().Select(e => e.GetString()!)];
        for (int i = 0; i < record.Samples.Count; i++)
        {
            FrameSample s = record.Samples[i];
            frame[i].Should().Be(s.Frame);
            (x[i] / 1000.0).Should().BeApproximately(s.Position.X, 0.0005 + 1e-6, $"frame {s.Frame}");
            (y[i] / 1000.0).Should().BeApproximately(s.Position.Y, 0.0005 + 1e-6, $"frame {s.Frame}");
            (z[i] / 1000.0).Should().BeApproximately(s.Position.Z, 0.0005 + 1e-6, $"frame {s.Frame}");
            (eyeZ[i] / 1000.0).Should().BeApproximately(s.Camera.Eye.Z, 0.0005 + 1e-6, $"frame {s.Frame}");
            cellIds[cell[i]].Should().Be($"0x{s.CellId:X8}");
            outcomes[outcome[i]].Should().Be(s.Refusal?.ToString() ?? (s.Slide is not null ? nameof(ResolveOutcome.Slid) : nameof(ResolveOutcome.Moved)));
        }

        data.RootElement.GetProperty("cells").GetArrayLength().Should().Be(world.Cells.Count);
        data.RootElement.GetProperty("objects").GetArrayLength().Should().Be(world.ObjectSurfaces.Count);
        data.RootElement.GetProperty("creatures").GetArrayLength().Should().Be(record.Creatures.Count(c => c.Samples.Count > 0));
    }

    [Fact]
    public void MainJob_PagePathIsAFolder_ExitsOneNamingThePage_TheSvgWritten()
    {
        string page = Path.Combine(_folder, "holtburg-walk.html");
        Directory.CreateDirectory(page);
        var error = new StringWriter();

        int status = MainJob.Run(["--out", _folder, "--frames", "30", "--quiet"], new StringWriter(), error);

        status.Should().Be(1);
        error.ToString().Should().Contain("cannot write").And.Contain(page);
        Directory.GetFiles(_folder).Select(Path.GetFileName).Should().BeEquivalentTo(["holtburg-walk.svg"], "no temporary file is left behind");
    }
}
