using System.Numerics;
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
    public void Page_DrawnSegments_AreWhatTheEngineDrewForEachFramesMove_EndingAtTheFramesFeet_WithAContactWhereAWallWasMet()
    {
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        WalkRecord plain = SceneRunner.Run(scene, world, 1700);
        WalkRecord record = SceneRunner.Run(scene, scene.CreateWorld(), 1700, null, new FrameDrawing());
        record.Samples.Select(s => (s.Position, s.CellId, s.IsOnGround)).Should().Equal(plain.Samples.Select(s => (s.Position, s.CellId, s.IsOnGround)), "drawing changes no answer");

        string html = WalkPage.Build(record, world);
        const string open = "<script type=\"application/json\" id=\"walk-data\">";
        int start = html.IndexOf(open, StringComparison.Ordinal) + open.Length;
        using JsonDocument data = JsonDocument.Parse(html[start..html.IndexOf("</script>", start, StringComparison.Ordinal)]);
        JsonElement drawn = data.RootElement.GetProperty("drawn");
        string[] kinds = [.. drawn.GetProperty("kinds").EnumerateArray().Select(e => e.GetString()!)];
        int sum = 0;
        int[] frame = [.. drawn.GetProperty("frame").EnumerateArray().Select(e => sum += e.GetInt32())];
        int[] kind = [.. drawn.GetProperty("kind").EnumerateArray().Select(e => e.GetInt32())];
        int[] ends = [.. drawn.GetProperty("ends").EnumerateArray().Select(e => e.GetInt32())];
        (frame.Length, kind.Length, ends.Length).Should().Be((record.Drawn.Count, record.Drawn.Count, 6 * record.Drawn.Count));
        frame.Length.Should().BeGreaterThan(record.Samples.Count, "every frame's move draws at least its sub-step and its floor");

        int walls = 0;
        for (int n = 1; n < record.Samples.Count; n++)
        {
            FrameSample s = record.Samples[n];
            int[] mine = [.. Enumerable.Range(0, frame.Length).Where(k => frame[k] == s.Frame)];
            int[] steps = [.. mine.Where(k => kinds[kind[k]] == nameof(DrawKind.SubStep))];
            if (steps.Length == 0)
            {
                s.Position.Should().Be(record.Samples[n - 1].Position, $"frame {s.Frame}: no sub-step drawn, so the feet did not move");
                continue;
            }

            int last = steps[^1];
            (ends[(6 * last) + 3], ends[(6 * last) + 4], ends[(6 * last) + 5]).Should().Be(
                (WalkPage.Millimetres(s.Position.X), WalkPage.Millimetres(s.Position.Y), WalkPage.Millimetres(s.Position.Z)), $"frame {s.Frame}: the last sub-step ends at the feet");
            if (s.Moved.Met.Wall.Kind is SurfaceKind.CellWall or SurfaceKind.BuildingShell or SurfaceKind.Mover or SurfaceKind.ObjectWall)
            {
                walls++;
                Vector3 normal = s.Moved.Met.Wall.Normal;
                mine.Should().Contain(k => kinds[kind[k]] == nameof(DrawKind.Contact)
                    && Vector3.Distance(Vector3.Normalize(new Vector3(ends[(6 * k) + 3] - ends[6 * k], ends[(6 * k) + 4] - ends[(6 * k) + 1], ends[(6 * k) + 5] - ends[(6 * k) + 2])), normal) < 0.02f,
                    $"frame {s.Frame}: a contact along the wall's normal {normal}");
            }
        }

        walls.Should().BeGreaterThan(10, "the walk slides along the cottage's walls, a creature and the door");
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
