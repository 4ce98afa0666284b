namespace AcDream.App;

/// <summary>Entry point of <c>dotnet run --project src/AcDream.App</c>.</summary>
internal static class Program
{
    private static int Main(string[] args) => MainJob.Run(args, Console.Out, Console.Error);
}
